// Medit / Gamma Mesh Format ASCII .mesh reader (libMeshb, https://github.com/LoicMarechal/libMeshb,
// whose keyword table and documentation describe the format; MeshVersionFormatted 1-4 only change
// the binary .meshb layout, which is not read).
//
// A file is "MeshVersionFormatted v", then keywords, each followed by its data: "Dimension 3",
// "Vertices n" and n lines "x y z ref", "Triangles n" and n lines "i j k ref", "Tetrahedra n" and
// n lines "i j k l ref" (1-based vertex numbers), ..., "End". '#' starts a comment. The ref of a
// tetrahedron is its region, that of a triangle its boundary tag. Other keywords (Edges, Corners,
// Ridges, Normals, ...) are read past: their data are numbers up to the next keyword.
// Second-order elements: "TetrahedraP2" (4 corners, then the nodes of edges (0,1) (1,2) (2,0)
// (0,3) (1,3) (2,3), kTetEdges' order, ref) and "TrianglesP2" (3 corners, then (0,1) (1,2) (2,0),
// ref), as Gmsh writes them (checked: gmsh 4.8 -order 2 to .mesh). Other volume elements
// (Hexahedra, Prisms, Pyramids, TetrahedraP3, ...) are refused.
#include "importers.h"

#include "file_cursor.h"
#include "readers.h"

#include <array>

namespace meshprep::detail {
namespace {

bool is_keyword(std::string_view token) {
  return !token.empty() && ((token[0] >= 'A' && token[0] <= 'Z') || (token[0] >= 'a' && token[0] <= 'z'));
}

bool starts_with(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

bool is_other_volume_element(std::string_view keyword) {
  return (starts_with(keyword, "Tetrahedra") && keyword != "Tetrahedra") || starts_with(keyword, "Hexahedra") ||
         starts_with(keyword, "Prisms") || starts_with(keyword, "Pyramids");
}

class MeditReader {
 public:
  MeditReader(const std::string& name, std::string_view data) : name_(name), in_(name, data, '#') {}

  TetFileContent read() {
    if (in_.at_end() || in_.token() != "MeshVersionFormatted")
      fail(name_, "not a Medit .mesh file (it does not start with MeshVersionFormatted)");
    const std::int64_t version = in_.integer("MeshVersionFormatted");
    if (version < 1 || version > 4) in_.fail_here("MeshVersionFormatted " + std::to_string(version) + " (1 to 4)");
    content_.format = "medit " + std::to_string(version);
    while (!in_.at_end()) {
      const std::string_view keyword = in_.token();
      if (keyword == "End") break;
      if (!is_keyword(keyword))
        in_.fail_here("expected a keyword such as Vertices or Tetrahedra, found " + quoted(keyword) +
                      " (is the count of the section before right?)");
      in_.set_context("the " + std::string(keyword) + " section");
      read_section(keyword);
    }
    return std::move(content_);
  }

 private:
  void read_section(std::string_view keyword) {
    if (keyword == "Dimension") {
      const std::int64_t dimension = in_.integer("Dimension");
      if (dimension != 3) in_.fail_here("Dimension " + std::to_string(dimension) + ": a tetrahedral mesh is 3D");
    } else if (keyword == "Vertices") {
      read_vertices();
    } else if (keyword == "Triangles") {
      read_elements("triangle", content_.triangles, content_.triangle_tags);
    } else if (keyword == "Tetrahedra") {
      read_elements("tetrahedron", content_.tets, content_.tet_regions);
    } else if (keyword == "TrianglesP2") {
      std::vector<std::array<std::uint32_t, 6>> triangles;
      read_elements("triangle", triangles, content_.triangle_tags);
      split_nodes(triangles, content_.triangles, content_.triangle_edge_nodes);
    } else if (keyword == "TetrahedraP2") {
      std::vector<std::array<std::uint32_t, 10>> tets;
      read_elements("tetrahedron", tets, content_.tet_regions);
      split_nodes(tets, content_.tets, content_.tet_edge_nodes);
    } else if (is_other_volume_element(keyword)) {
      const std::uint64_t count = in_.count(std::string(keyword).c_str());
      if (count > 0)
        in_.fail_here(std::to_string(count) + " " + std::string(keyword) + ": meshprep reads Tetrahedra and TetrahedraP2 only");
    } else {
      if (keyword == "Edges" || keyword == "Quadrilaterals") content_.elements_ignored += in_.count("element count");
      while (!in_.at_end() && !is_keyword(in_.peek_token())) in_.token();
    }
  }

  void read_vertices() {
    const std::uint64_t count = in_.count("number of vertices");
    content_.points.reserve(capped_count(count, in_.bytes_left(), 8));  // "0 0 0 0\n"
    for (std::uint64_t v = 0; v < count; ++v) {
      Vec3 p;
      for (int c = 0; c < 3; ++c) p[c] = in_.real("coordinate");
      in_.integer("vertex reference");
      content_.points.push_back(p);
    }
  }

  template <std::size_t N>
  void read_elements(const char* element, std::vector<std::array<std::uint32_t, N>>& elements, std::vector<int>& refs) {
    const std::uint64_t count = in_.count("number of elements");
    const std::size_t reserve = capped_count(count, in_.bytes_left(), 2 * N + 2);
    elements.reserve(elements.size() + reserve);
    refs.reserve(refs.size() + reserve);
    const std::size_t num_points = content_.points.size();
    for (std::uint64_t e = 0; e < count; ++e) {
      std::array<std::uint32_t, N> corners{};
      for (std::size_t k = 0; k < N; ++k) {
        const std::int64_t number = in_.integer("vertex number");
        if (!in_numbering(number, 1, num_points))
          fail_node_reference(name_, in_.where(), element, e + 1, number, 1, num_points);
        corners[k] = static_cast<std::uint32_t>(number - 1);
      }
      elements.push_back(corners);
      refs.push_back(tag_from_file(name_, in_.where(), "reference", in_.integer("reference")));
    }
  }

  const std::string& name_;
  FileCursor in_;
  TetFileContent content_;
};

}  // namespace

TetFileContent read_medit(const std::string& name, std::string_view data) { return MeditReader(name, data).read(); }

}  // namespace meshprep::detail
