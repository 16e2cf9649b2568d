// Abaqus / CalculiX input deck .inp with linear tetrahedra (C3D4) or second-order ones (C3D10),
// 1-based node and element ids (tet t is element t + 1):
//   *NODE; one *ELEMENT, TYPE=C3D4 (or C3D10), ELSET=REGION_<r> block per region;
//   per boundary tag: *NSET, NSET=BOUNDARY_<t> (the nodes of its faces, mid-edge nodes included)
//   and an element-face surface *SURFACE, NAME=SURF_<t>, TYPE=ELEMENT with "element, S<k>" lines.
// Data lines hold at most 16 entries (the Abaqus limit for set definitions).
//
// Orientation: C3D4 nodes 1-2-3 are counter-clockwise seen from node 4, i.e. positive volume in
// TetMesh's sense, so tets are written in their own order. Faces (Abaqus Analysis User's Guide,
// "Three-dimensional solid element library"; CalculiX manual, C3D4): S1 = 1-2-3, S2 = 1-4-2,
// S3 = 2-4-3, S4 = 3-4-1, each listed with its normal pointing into the element.
//
// C3D10: corners 1-4 as C3D4's, then nodes 5-10 on edges 1-2, 2-3, 3-1, 1-4, 2-4, 3-4 (Abaqus
// Analysis User's Guide, "Three-dimensional solid element library", node ordering figure;
// CalculiX CrunchiX manual, "Ten-node tetrahedral element (C3D10)"): kTetEdges' order, checked
// on what `gmsh -3 -order 2` writes to .inp. Its faces are numbered as C3D4's, so the surfaces
// are written alike.
#include "exporters.h"

#include "meshprep/core/atomic_file.h"
#include "meshprep/core/errors.h"

#include <algorithm>
#include <array>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace meshprep::detail {
namespace {

constexpr std::size_t max_entries_per_line = 16;

// Local C3D4 faces, 0-based (S1..S4).
constexpr std::array<std::array<int, 3>, 4> c3d4_faces{{{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}}};

struct FaceOwner {
  std::size_t tet;
  int face;  // 1..4 for S1..S4
};

// The rotation of a triangle that starts at its smallest vertex: equal for equally oriented copies.
Triangle canonical(const Triangle& t) {
  const auto first = std::min_element(t.begin(), t.end()) - t.begin();
  return {t[first], t[(first + 1) % 3], t[(first + 2) % 3]};
}

// For each (outward) boundary face, the tet having it as an outward face and the face's number.
std::vector<FaceOwner> face_owners(const TetMesh& mesh, const std::string& path) {
  std::multimap<Triangle, std::size_t> boundary;
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) boundary.emplace(canonical(mesh.boundary_faces[f]), f);
  constexpr FaceOwner none{0, 0};
  std::vector<FaceOwner> owners(mesh.boundary_faces.size(), none);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (int k = 0; k < 4; ++k) {
      const auto& local = c3d4_faces[k];
      const Tetrahedron& tet = mesh.tets[t];
      // Reversed: the outward orientation of a face listed inward.
      const auto range = boundary.equal_range(canonical({tet[local[0]], tet[local[2]], tet[local[1]]}));
      for (auto it = range.first; it != range.second; ++it)
        if (owners[it->second].face == none.face) owners[it->second] = {t, k + 1};
    }
  for (std::size_t f = 0; f < owners.size(); ++f)
    if (owners[f].face == none.face)
      throw InvalidInput(path + ": cannot export: boundary face " + std::to_string(f) +
                         " is not an outward face of any tetrahedron (needed for the *SURFACE)");
  return owners;
}

std::map<int, std::vector<std::size_t>> group_by_tag(const std::vector<int>& tags) {
  std::map<int, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < tags.size(); ++i) groups[tags[i]].push_back(i);
  return groups;
}

// Comma-separated, at most max_entries_per_line per line.
void write_id_list(std::ostream& out, const std::vector<std::size_t>& ids) {
  for (std::size_t i = 0; i < ids.size(); ++i) {
    out << ids[i];
    const bool line_end = (i + 1) % max_entries_per_line == 0 || i + 1 == ids.size();
    out << (line_end ? "\n" : ", ");
  }
}

void write_nodes(std::ostream& out, const TetMesh& mesh) {
  out << "*NODE\n";
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    out << v + 1 << ", ";
    write_point(out, mesh.points[v], ", ");
    out << '\n';
  }
}

const char* element_type(const TetMesh& mesh) { return mesh.quadratic() ? "C3D10" : "C3D4"; }

// One line per element: 11 entries at most for C3D10, within the 16 of a data line.
void write_elements(std::ostream& out, const TetMesh& mesh) {
  for (const auto& [region, tets] : group_by_tag(mesh.tet_regions)) {
    out << "*ELEMENT, TYPE=" << element_type(mesh) << ", ELSET=REGION_" << region << '\n';
    for (std::size_t t : tets) {
      out << t + 1;
      for (std::uint32_t v : mesh.tets[t]) out << ", " << v + std::size_t{1};
      if (mesh.quadratic())
        for (std::uint32_t v : mesh.tet_edge_nodes[t]) out << ", " << v + std::size_t{1};
      out << '\n';
    }
  }
}

void write_boundaries(std::ostream& out, const TetMesh& mesh, const std::vector<FaceOwner>& owners) {
  const std::vector<std::array<std::uint32_t, 3>> face_nodes = boundary_face_edge_nodes(mesh);
  for (const auto& [tag, faces] : group_by_tag(mesh.boundary_tags)) {
    std::vector<std::size_t> nodes;
    for (std::size_t f : faces) {
      for (std::uint32_t v : mesh.boundary_faces[f]) nodes.push_back(v + std::size_t{1});
      if (mesh.quadratic())
        for (std::uint32_t v : face_nodes[f]) nodes.push_back(v + std::size_t{1});
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    out << "*NSET, NSET=BOUNDARY_" << tag << '\n';
    write_id_list(out, nodes);
    out << "*SURFACE, NAME=SURF_" << tag << ", TYPE=ELEMENT\n";
    for (std::size_t f : faces) out << owners[f].tet + 1 << ", S" << owners[f].face << '\n';
  }
}

}  // namespace

void write_abaqus(const TetMesh& mesh, const std::string& path) {
  const std::vector<FaceOwner> owners = face_owners(mesh, path);
  write_file_atomically(path, [&](std::ostream& out) {
    out << "*HEADING\n"
        << "meshprep tetrahedral mesh: " << mesh.points.size() << " nodes, " << mesh.tets.size() << ' ' << element_type(mesh) << " elements\n";
    write_nodes(out, mesh);
    write_elements(out, mesh);
    write_boundaries(out, mesh, owners);
  });
}

}  // namespace meshprep::detail
