// TetGen .node/.ele/.face reader (TetGen 1.5 manual, section 5.2;
// https://wias-berlin.de/software/tetgen/fformats.html):
//   .node  "<#points> [<dimension = 3> [<#attributes> [<#boundary markers 0|1>]]]", then "<i> <x> <y> <z> ..."
//   .ele   "<#tets> [<nodes per tet = 4> [<#attributes>]]",                      then "<i> <n1> <n2> <n3> <n4> [<region> ...]"
//   .face  "<#faces> [<#boundary markers 0|1>]",                                 then "<i> <n1> <n2> <n3> [<marker>]"
// '#' starts a comment. Each file numbers its items consecutively from 0 or 1 (TetGen -z writes
// 0-based files), and node references use the .node file's first number. What a line holds after
// the values read here (point attributes and markers, further tet attributes, the neighbours of
// TetGen -nn) is ignored, as TetGen's own reader does. The first .ele attribute is the region
// and the .face marker the boundary tag (TetGen writes integers, possibly as reals such as
// "2.0"; a real that is not an integer is refused).
#include "importers.h"

#include "file_cursor.h"
#include "readers.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>

namespace meshprep::detail {
namespace {

// One TetGen file: its header line, then one record per line.
class TetgenFile {
 public:
  TetgenFile(const std::string& name, std::string_view text) : name_(name), in_(name, text, '#') {}

  // The header: the item count, then up to `optional.size()` more values (defaults kept when absent).
  template <std::size_t N>
  std::uint64_t header(const char* what, std::array<std::int64_t, N>& optional) {
    in_.set_context("the header");
    const std::uint64_t count = in_.count(what);
    for (std::int64_t& value : optional) {
      if (in_.at_line_end()) break;
      value = in_.integer_of(in_.field("header value"), "header value");
    }
    in_.set_context(std::string("the ") + what + "'s lines");
    return count;
  }

  // Starts record r (0-based) at the next line: its number must follow the previous one.
  void record(std::uint64_t r) {
    in_.skip_line();
    const std::int64_t number = in_.integer("item number");
    if (r == 0) {
      if (number != 0 && number != 1) in_.fail_here("the first item is numbered " + std::to_string(number) + " (0 or 1)");
      first_ = number;
    } else if (number != first_ + static_cast<std::int64_t>(r)) {
      in_.fail_here("item numbered " + std::to_string(number) + ", expected " +
                    std::to_string(first_ + static_cast<std::int64_t>(r)) + " (the items are numbered consecutively)");
    }
  }

  double real(const char* what) { return in_.real_of(in_.field(what), what); }
  std::int64_t integer(const char* what) { return in_.integer_of(in_.field(what), what); }
  bool at_line_end() { return in_.at_line_end(); }
  std::string where() const { return in_.where(); }
  [[noreturn]] void fail_here(const std::string& problem) const { in_.fail_here(problem); }
  std::size_t bytes_left() const { return in_.bytes_left(); }
  std::int64_t first() const { return first_; }
  const std::string& name() const { return name_; }

 private:
  const std::string& name_;
  FileCursor in_;
  std::int64_t first_ = 1;
};

// The `extra` values the header announces after what is read of a line (attributes, markers):
// ignored, as TetGen ignores them, but they must be there - a header announcing a billion
// attributes that no line holds is a lie like any other count (issue 45, item 12).
void skip_announced(TetgenFile& file, std::int64_t extra, const char* what) {
  for (std::int64_t i = 0; i < extra; ++i)
    if (file.at_line_end())
      file.fail_here("the header announces " + std::to_string(extra) + " more " + what +
                     " per line than this line holds");
    else
      file.real(what);
}

// `count` elements of N corners, each followed by its label (region, marker) unless `label` is
// null, then `extra` values announced by the header.
template <std::size_t N>
void read_elements(TetgenFile& file, const char* element, std::uint64_t count, const char* label, std::int64_t extra,
                   std::int64_t node_first, std::size_t num_points, std::vector<std::array<std::uint32_t, N>>& elements,
                   std::vector<int>& labels) {
  const std::size_t reserve = capped_count(count, file.bytes_left(), 2 * N + 2);  // "1 1 2 3\n"
  elements.reserve(reserve);
  labels.reserve(reserve);
  for (std::uint64_t e = 0; e < count; ++e) {
    file.record(e);
    const std::size_t number = static_cast<std::size_t>(file.first()) + e;
    std::array<std::uint32_t, N> corners{};
    for (std::uint32_t& corner : corners) {
      const std::int64_t node = file.integer("node number");
      if (!in_numbering(node, node_first, num_points))
        fail_node_reference(file.name(), file.where(), element, number, node, node_first, num_points);
      corner = static_cast<std::uint32_t>(node - node_first);
    }
    elements.push_back(corners);
    std::optional<int> tag = 0;
    if (label) {
      const double value = file.real(label);
      if (!(tag = integral_tag(value))) file.fail_here(std::string(label) + " " + number_text(value) + " is not an integer");
    }
    skip_announced(file, extra, "attribute values");
    labels.push_back(*tag);
  }
}

void read_nodes(TetgenFile& file, TetFileContent& content) {
  std::array<std::int64_t, 3> header{3, 0, 0};  // dimension, attributes, markers
  const std::uint64_t count = file.header("node", header);
  if (header[0] != 3) file.fail_here("dimension " + std::to_string(header[0]) + ": a tetrahedral mesh is 3D");
  if (header[1] < 0) file.fail_here(std::to_string(header[1]) + " point attributes (a count, at least 0)");
  if (header[2] != 0 && header[2] != 1) file.fail_here(std::to_string(header[2]) + " boundary markers (0 or 1)");
  content.points.reserve(capped_count(count, file.bytes_left(), 8));  // "1 0 0 0\n"
  for (std::uint64_t v = 0; v < count; ++v) {
    file.record(v);
    Vec3 p;
    for (int c = 0; c < 3; ++c) p[c] = file.real("coordinate");
    skip_announced(file, header[1] + header[2], "attribute values and markers");
    content.points.push_back(p);
  }
}

void read_tets(TetgenFile& file, std::int64_t node_first, TetFileContent& content) {
  std::array<std::int64_t, 2> header{4, 0};  // nodes per tet, attributes
  const std::uint64_t count = file.header("tetrahedron", header);
  if (header[0] != 4)
    file.fail_here(std::to_string(header[0]) + " nodes per tetrahedron: meshprep reads linear (4-node) tetrahedra only");
  if (header[1] < 0) file.fail_here(std::to_string(header[1]) + " tetrahedron attributes (a count, at least 0)");
  read_elements(file, "tetrahedron", count, header[1] > 0 ? "region attribute" : nullptr, std::max<std::int64_t>(header[1] - 1, 0),
                node_first, content.points.size(), content.tets, content.tet_regions);
}

void read_faces(TetgenFile& file, std::int64_t node_first, TetFileContent& content) {
  std::array<std::int64_t, 1> header{0};  // boundary markers
  const std::uint64_t count = file.header("face", header);
  if (header[0] != 0 && header[0] != 1) file.fail_here(std::to_string(header[0]) + " boundary markers (0 or 1)");
  read_elements(file, "face", count, header[0] > 0 ? "boundary marker" : nullptr, 0, node_first, content.points.size(),
                content.triangles, content.triangle_tags);
}

}  // namespace

TetFileContent read_tetgen(const TetgenTexts& texts) {
  TetFileContent content;
  content.points_file = texts.node_name;
  TetgenFile node(texts.node_name, texts.node);
  read_nodes(node, content);
  TetgenFile ele(texts.ele_name, texts.ele);
  read_tets(ele, node.first(), content);
  if (texts.face) {
    TetgenFile face(texts.face_name, *texts.face);
    read_faces(face, node.first(), content);
  }
  content.format = std::string("tetgen ") + (node.first() == 0 ? "0-based" : "1-based") + (texts.face ? " with .face" : "");
  return content;
}

}  // namespace meshprep::detail
