// Gmsh .msh reader: MSH 4.1 and 2.x (2.0-2.2), ASCII and binary (Gmsh reference manual, "MSH file
// format" and "MSH file format version 2 (Legacy)"; https://gmsh.info/doc/texinfo/gmsh.html#MSH-file-format).
//
// Binary files: the section names and, in 2.x, the counts after $Nodes and $Elements are text
// lines; the data is raw: int = 4 bytes, double = 8 bytes, size_t (4.1) = the header's data-size,
// all in the byte order that the int 1 after the header reveals (a file from a big-endian machine
// reads as well).
//
// Tags: in 2.x each element carries its physical tag first (then the elementary one); in 4.1 an
// element belongs to the entity of its block, whose first physical tag ($Entities) is the
// element's. Physical tags are the region of tets and the boundary tag of triangles (0 = none).
// Node tags are any positive numbers, not necessarily consecutive.
//
// Order: points in node-tag order and elements in element-tag order, whatever the order of the
// blocks (a 4.1 file lists nodes and elements grouped by entity); for a file write_tet_mesh wrote,
// that is the mesh's own order.
//
// Elements: tets and triangles, linear (types 4, 2) or second-order (11, 9; their mid-edge nodes
// put in kTetEdges' order, gmsh_elements.h) are read; points, lines, quadrangles and other
// higher-order surface elements are skipped (counted); other volume elements are refused, as are
// element types outside the manual's list (1-31), whose node count this reader does not know.
#include "gmsh_elements.h"
#include "importers.h"

#include "file_cursor.h"
#include "readers.h"

#include <algorithm>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <utility>

namespace meshprep::detail {
namespace {

struct ElementType {
  int nodes;
  int dimension;
  const char* name;
};

// The element types 1-31 of the manual's list.
const ElementType element_types[] = {
    {2, 1, "2-node line"},          {3, 2, "3-node triangle"},       {4, 2, "4-node quadrangle"},
    {4, 3, "4-node tetrahedron"},   {8, 3, "8-node hexahedron"},     {6, 3, "6-node prism"},
    {5, 3, "5-node pyramid"},       {3, 1, "3-node line"},           {6, 2, "6-node triangle"},
    {9, 2, "9-node quadrangle"},    {10, 3, "10-node tetrahedron"},  {27, 3, "27-node hexahedron"},
    {18, 3, "18-node prism"},       {14, 3, "14-node pyramid"},      {1, 0, "point"},
    {8, 2, "8-node quadrangle"},    {20, 3, "20-node hexahedron"},   {15, 3, "15-node prism"},
    {13, 3, "13-node pyramid"},     {9, 2, "9-node triangle"},       {10, 2, "10-node triangle"},
    {12, 2, "12-node triangle"},    {15, 2, "15-node triangle"},     {15, 2, "15-node triangle"},
    {21, 2, "21-node triangle"},    {4, 1, "4-node line"},           {5, 1, "5-node line"},
    {6, 1, "6-node line"},          {20, 3, "20-node tetrahedron"},  {35, 3, "35-node tetrahedron"},
    {56, 3, "56-node tetrahedron"},
};

enum class Version { V2, V41 };

// The numbers of a .msh file: text tokens (ASCII) or raw values (binary).
class MshSource {
 public:
  MshSource(const std::string& name, std::string_view data) : in_(name, data) {}

  FileCursor& cursor() { return in_; }
  // In a binary file, the data after a text line starts at the next line's first byte.
  void start_data() {
    if (in_.binary()) in_.start_binary_data();
  }
  void set_size_bytes(std::size_t size_bytes) { size_bytes_ = size_bytes; }

  // A count or tag written as size_t (MSH 4.1).
  std::uint64_t size(const char* what) {
    if (!in_.binary()) return in_.count(what);
    return size_bytes_ == 4 ? in_.load<std::uint32_t>() : in_.load<std::uint64_t>();
  }
  // An int (a 2.x node number, element type, tag; a 4.1 entity tag or dimension).
  std::int64_t integer(const char* what) { return in_.binary() ? in_.load<std::int32_t>() : in_.integer(what); }
  double real(const char* what) { return in_.binary() ? in_.load<double>() : in_.real(what); }

  // Moves past "$End<section>" without reading the section.
  void skip_section(std::string_view section) {
    const std::string end = end_of(section);
    if (in_.binary()) {  // the data may hold anything, the end marker is a text line
      if (!in_.skip_past(end)) in_.fail_truncated();
      return;
    }
    while (in_.token() != end) in_.skip_line();
  }
  void expect_end(std::string_view section) {
    const std::string end = end_of(section);
    const std::string_view t = in_.token();
    if (t != end) in_.fail_here("expected " + end + ", found " + quoted(t) + " (are the counts right?)");
  }

 private:
  static std::string end_of(std::string_view section) { return "$End" + std::string(section.substr(1)); }

  FileCursor in_;
  std::size_t size_bytes_ = 8;
};

// The permutation that sorts `tags` (stably: equal tags keep their file order).
std::vector<std::size_t> tag_order(const std::vector<std::uint64_t>& tags) {
  std::vector<std::size_t> order(tags.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return tags[a] < tags[b]; });
  return order;
}

template <class T>
void permute(std::vector<T>& values, const std::vector<std::size_t>& order) {
  std::vector<T> permuted;
  permuted.reserve(values.size());
  for (const std::size_t i : order) permuted.push_back(values[i]);
  values = std::move(permuted);
}

// Puts elements, their tags and their mid-edge nodes (if every element has them: a file mixing
// orders is refused later) in element-tag order (a 4.1 file lists them by entity).
template <class Element, class EdgeNodes>
void sort_by_tag(std::vector<std::uint64_t>& tags, std::vector<Element>& elements, std::vector<int>& labels,
                 std::vector<EdgeNodes>& edge_nodes) {
  if (std::is_sorted(tags.begin(), tags.end())) return;
  const std::vector<std::size_t> order = tag_order(tags);
  permute(tags, order);
  permute(elements, order);
  permute(labels, order);
  if (edge_nodes.size() == elements.size()) permute(edge_nodes, order);
}

// Node tags -> point indices. The points are put in node-tag order (a 4.1 file lists them by
// entity); tags are usually 1..n (a direct offset), else looked up by binary search.
class NodeTags {
 public:
  void reserve(std::size_t count) { tags_.reserve(count); }
  void add(std::uint64_t tag) { tags_.push_back(tag); }
  std::size_t size() const { return tags_.size(); }

  void finish(std::vector<Vec3>& points, const std::string& name) {
    if (!std::is_sorted(tags_.begin(), tags_.end())) {
      const std::vector<std::size_t> order = tag_order(tags_);
      permute(tags_, order);
      permute(points, order);
    }
    const auto repeated = std::adjacent_find(tags_.begin(), tags_.end());
    if (repeated != tags_.end()) fail(name, "node " + std::to_string(*repeated) + " is defined twice");
    contiguous_ = tags_.empty() || tags_.back() - tags_.front() == tags_.size() - 1;
  }

  bool find(std::uint64_t tag, std::uint32_t& index) const {
    if (contiguous_) {
      if (tags_.empty() || tag < tags_.front() || tag - tags_.front() >= tags_.size()) return false;
      index = static_cast<std::uint32_t>(tag - tags_.front());
      return true;
    }
    const auto it = std::lower_bound(tags_.begin(), tags_.end(), tag);
    if (it == tags_.end() || *it != tag) return false;
    index = static_cast<std::uint32_t>(it - tags_.begin());
    return true;
  }

 private:
  std::vector<std::uint64_t> tags_;  // sorted once finished
  bool contiguous_ = true;
};

class GmshReader {
 public:
  GmshReader(const std::string& name, std::string_view data) : name_(name), msh_(name, data), in_(msh_.cursor()) {}

  TetFileContent read() {
    read_header();
    while (!in_.at_end()) {
      const std::string_view section = in_.token();
      if (section.size() < 2 || section[0] != '$')
        in_.fail_here("expected a section such as $Nodes or $Elements, found " + quoted(section));
      if (section.substr(0, 4) == "$End") in_.fail_here("unexpected " + quoted(section));
      in_.set_context("the " + std::string(section) + " section");
      if (section == "$Nodes") {
        if (nodes_read_) in_.fail_here("a second $Nodes section");
        version_ == Version::V41 ? read_nodes_41() : read_nodes_2();
        nodes_.finish(content_.points, name_);
        nodes_read_ = true;
      } else if (section == "$Elements") {
        if (elements_read_) in_.fail_here("a second $Elements section");
        version_ == Version::V41 ? read_elements_41() : read_elements_2();
        sort_by_tag(tet_tags_, content_.tets, content_.tet_regions, content_.tet_edge_nodes);
        sort_by_tag(triangle_tags_, content_.triangles, content_.triangle_tags, content_.triangle_edge_nodes);
        elements_read_ = true;
      } else if (section == "$Entities" && version_ == Version::V41) {
        read_entities_41();
      } else if (section == "$PhysicalNames") {
        read_physical_names();
      } else if (section == "$PartitionedEntities") {
        in_.fail_here("partitioned meshes are not supported (save the mesh unpartitioned)");
      } else {
        msh_.skip_section(section);
        continue;
      }
      msh_.expect_end(section);
    }
    return std::move(content_);
  }

 private:
  void read_header() {
    if (in_.at_end() || in_.token() != "$MeshFormat")
      fail(name_, "not a Gmsh .msh file (it does not start with $MeshFormat)");
    const std::string_view version = in_.token();
    if (version == "4.1") {
      version_ = Version::V41;
    } else if (version == "2" || version == "2.0" || version == "2.1" || version == "2.2") {
      version_ = Version::V2;
    } else {
      in_.fail_here("MSH version " + quoted(version) + " is not supported (4.1 and 2.x are; save as one of them)");
    }
    const std::uint64_t file_type = in_.count("file-type");
    const std::uint64_t data_size = in_.count("data-size");
    if (file_type > 1) in_.fail_here("file-type " + std::to_string(file_type) + " (0 = ASCII, 1 = binary)");
    if (data_size != 8 && !(version_ == Version::V41 && data_size == 4))
      in_.fail_here("data-size " + std::to_string(data_size) + " is not supported (8)");
    content_.format = std::string("msh ") + (version_ == Version::V41 ? "4.1" : std::string(version)) +
                      (file_type == 1 ? " binary" : " ascii");
    if (file_type == 1) {
      // The int 1, written in the file's byte order.
      in_.set_binary(/*little_endian=*/true);
      msh_.set_size_bytes(data_size);
      msh_.start_data();
      const std::string_view one = in_.bytes(4);
      if (load_value<std::int32_t>(one.data(), /*little_endian=*/false) == 1)
        in_.set_binary(/*little_endian=*/false);
      else if (load_value<std::int32_t>(one.data(), /*little_endian=*/true) != 1)
        in_.fail_here("the int after the binary header is not 1 in either byte order");
    }
    msh_.expect_end("$MeshFormat");
  }

  // ---- $PhysicalNames (text in ASCII and binary files): lines `dimension tag "name"` ----
  void read_physical_names() {
    const std::uint64_t count = in_.count("number of physical names");
    for (std::uint64_t i = 0; i < count; ++i) {
      const std::int64_t dimension = in_.integer("physical dimension");
      const int tag = tag_from_file(name_, in_.where(), "physical tag", in_.integer("physical tag"));
      std::string_view quoted_name = in_.rest_of_line();
      if (quoted_name.size() < 2 || quoted_name.front() != '"' || quoted_name.back() != '"')
        in_.fail_here("a physical name is written in double quotes, found " + quoted(quoted_name));
      const std::string physical_name(quoted_name.substr(1, quoted_name.size() - 2));
      if (dimension == 2) content_.triangle_names[tag] = physical_name;
      if (dimension == 3) content_.region_names[tag] = physical_name;
    }
  }

  // ---- $Entities (4.1): the first physical tag of each surface and volume ----

  void read_entities_41() {
    msh_.start_data();
    std::uint64_t counts[4];
    for (std::uint64_t& count : counts) count = msh_.size("number of entities");
    for (int dimension = 0; dimension < 4; ++dimension) {
      for (std::uint64_t e = 0; e < counts[dimension]; ++e) {
        const std::int64_t tag = msh_.integer("entity tag");
        declared_entities_.insert({dimension, tag});
        for (int c = 0; c < (dimension == 0 ? 3 : 6); ++c) msh_.real("entity bounding box");
        const std::uint64_t num_physicals = msh_.size("number of physical tags");
        for (std::uint64_t p = 0; p < num_physicals; ++p) {
          const std::int64_t physical = msh_.integer("physical tag");
          if (p == 0) physical_of_[{dimension, tag}] = tag_from_file(name_, in_.where(), "physical tag", physical);
        }
        if (dimension == 0) continue;
        const std::uint64_t num_bounding = msh_.size("number of bounding entities");
        for (std::uint64_t b = 0; b < num_bounding; ++b) msh_.integer("bounding entity tag");
      }
    }
  }

  // ---- $Nodes ----

  void read_nodes_41() {
    msh_.start_data();
    const std::uint64_t num_blocks = msh_.size("number of node blocks");
    const std::uint64_t num_nodes = msh_.size("number of nodes");
    msh_.size("smallest node tag");
    msh_.size("largest node tag");
    reserve_points(num_nodes, in_.binary() ? 32 : 8);  // tag and x y z
    for (std::uint64_t b = 0; b < num_blocks; ++b) {
      const std::int64_t dimension = msh_.integer("entity dimension");
      msh_.integer("entity tag");
      const std::int64_t parametric = msh_.integer("parametric flag");
      const std::uint64_t count = msh_.size("number of nodes in the block");
      if (dimension < 0 || dimension > 3) in_.fail_here("node block of entity dimension " + std::to_string(dimension));
      if (parametric != 0 && parametric != 1) in_.fail_here("parametric flag " + std::to_string(parametric) + " (0 or 1)");
      const auto extra = static_cast<int>(parametric * dimension);  // u, v, w after x y z
      const std::size_t first = nodes_.size();
      for (std::uint64_t n = 0; n < count; ++n) nodes_.add(msh_.size("node tag"));
      for (std::size_t n = first; n < nodes_.size(); ++n) {
        read_point();
        for (int k = 0; k < extra; ++k) msh_.real("parametric coordinate");
      }
    }
    if (nodes_.size() != num_nodes)
      in_.fail_here("the $Nodes header announces " + std::to_string(num_nodes) + " nodes, its blocks hold " +
                    std::to_string(nodes_.size()));
  }

  void read_nodes_2() {
    const std::uint64_t num_nodes = in_.count("number of nodes");
    msh_.start_data();
    reserve_points(num_nodes, in_.binary() ? 28 : 8);
    for (std::uint64_t n = 0; n < num_nodes; ++n) {
      const std::int64_t tag = msh_.integer("node number");
      if (tag < 0) in_.fail_here("negative node number " + std::to_string(tag));
      nodes_.add(static_cast<std::uint64_t>(tag));
      read_point();
    }
  }

  void reserve_points(std::uint64_t announced, std::size_t min_bytes_each) {
    const std::size_t count = capped_count(announced, in_.bytes_left(), min_bytes_each);
    nodes_.reserve(count);
    content_.points.reserve(count);
  }

  void read_point() {
    Vec3 p;
    for (int c = 0; c < 3; ++c) p[c] = msh_.real("coordinate");
    content_.points.push_back(p);
  }

  // ---- $Elements ----

  const ElementType& element_type(std::int64_t type, std::int64_t element) {
    if (type < 1 || type > static_cast<std::int64_t>(std::size(element_types)))
      in_.fail_here("element " + std::to_string(element) + " has type " + std::to_string(type) +
                    ", which this reader does not know (types 1-31 are read)");
    const ElementType& t = element_types[type - 1];
    if (t.dimension == 3 && type != gmsh_tetrahedron && type != gmsh_tetrahedron_10)
      in_.fail_here("element " + std::to_string(element) + " is a " + t.name + " (type " + std::to_string(type) +
                    "); meshprep reads tetrahedra of 4 and 10 nodes (types 4, 11) only");
    return t;
  }

  // The nodes of one element (4.1: size_t tags, 2.x: ints) into a tet or a triangle; other
  // (lower-dimensional) types are counted and dropped.
  void read_element(std::int64_t type, const ElementType& t, std::int64_t element, int physical) {
    std::uint32_t nodes[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (int k = 0; k < t.nodes; ++k) {
      const std::uint64_t tag = version_ == Version::V41 ? msh_.size("node tag")
                                                         : static_cast<std::uint64_t>(msh_.integer("node number"));
      std::uint32_t index = 0;
      if (!nodes_.find(tag, index))
        in_.fail_here("element " + std::to_string(element) + " references node " +
                      std::to_string(static_cast<std::int64_t>(tag)) + ", which $Nodes does not define (" +
                      std::to_string(nodes_.size()) + " nodes)");
      if (k < 10) nodes[k] = index;
    }
    if (type == gmsh_tetrahedron || type == gmsh_tetrahedron_10) {
      content_.tets.push_back({nodes[0], nodes[1], nodes[2], nodes[3]});
      tet_tags_.push_back(static_cast<std::uint64_t>(element));
      content_.tet_regions.push_back(physical);
      if (type == gmsh_tetrahedron_10) {
        TetEdgeNodes edge_nodes{};
        for (int k = 0; k < 6; ++k) edge_nodes[kGmshTetEdges[k]] = nodes[4 + k];
        content_.tet_edge_nodes.push_back(edge_nodes);
      }
    } else if (type == gmsh_triangle || type == gmsh_triangle_6) {
      content_.triangles.push_back({nodes[0], nodes[1], nodes[2]});
      triangle_tags_.push_back(static_cast<std::uint64_t>(element));
      content_.triangle_tags.push_back(physical);
      if (type == gmsh_triangle_6) content_.triangle_edge_nodes.push_back({nodes[3], nodes[4], nodes[5]});
    } else {
      ++content_.elements_ignored;
    }
  }

  bool declares_dimension(std::int64_t dimension) const {
    const auto first = declared_entities_.lower_bound({dimension, std::numeric_limits<std::int64_t>::min()});
    return first != declared_entities_.end() && first->first == dimension;
  }

  int physical_of(std::int64_t dimension, std::int64_t entity) const {
    const auto it = physical_of_.find({dimension, entity});
    return it == physical_of_.end() ? 0 : it->second;
  }

  void read_elements_41() {
    msh_.start_data();
    const std::uint64_t num_blocks = msh_.size("number of element blocks");
    const std::uint64_t num_elements = msh_.size("number of elements");
    msh_.size("smallest element tag");
    msh_.size("largest element tag");
    reserve_elements(num_elements, in_.binary() ? 40 : 10);  // tag and 4 nodes
    std::uint64_t read = 0;
    for (std::uint64_t b = 0; b < num_blocks; ++b) {
      const std::int64_t dimension = msh_.integer("entity dimension");
      const std::int64_t entity = msh_.integer("entity tag");
      const std::int64_t type = msh_.integer("element type");
      const std::uint64_t count = msh_.size("number of elements in the block");
      // An entity $Entities does not declare, among those it declares of that dimension, has no
      // physical tag to give: its elements would get a default region without a word (issue 45,
      // item 12). meshio declares none (its $Entities is empty): then no block is refused.
      if (declares_dimension(dimension) && !declared_entities_.count({dimension, entity}))
        in_.fail_here("an element block on entity " + std::to_string(entity) + " of dimension " +
                      std::to_string(dimension) + ", which $Entities does not declare");
      const int physical = physical_of(dimension, entity);
      for (std::uint64_t e = 0; e < count; ++e, ++read) {
        const auto element = static_cast<std::int64_t>(msh_.size("element tag"));
        read_element(type, element_type(type, element), element, physical);
      }
    }
    if (read != num_elements)
      in_.fail_here("the $Elements header announces " + std::to_string(num_elements) + " elements, its blocks hold " +
                    std::to_string(read));
  }

  void read_elements_2() {
    const std::uint64_t num_elements = in_.count("number of elements");
    msh_.start_data();
    reserve_elements(num_elements, in_.binary() ? 28 : 10);
    // ASCII: "number type num-tags tags... nodes..." per element. Binary: blocks of elements of one
    // type under a header "type count num-tags", each element "number tags... nodes...".
    std::int64_t type = 0, num_tags = 0;
    std::uint64_t left_in_block = 0;
    for (std::uint64_t e = 0; e < num_elements; ++e) {
      if (in_.binary() && left_in_block == 0) {
        type = msh_.integer("element type");
        const std::int64_t count = msh_.integer("number of elements in the block");
        num_tags = msh_.integer("number of tags");
        if (count <= 0 || static_cast<std::uint64_t>(count) > num_elements - e)
          in_.fail_here("element block of " + std::to_string(count) + " elements, but " +
                        std::to_string(num_elements - e) + " are left to read");
        left_in_block = static_cast<std::uint64_t>(count);
      }
      const std::int64_t number = msh_.integer("element number");
      if (!in_.binary()) {
        type = msh_.integer("element type");
        num_tags = msh_.integer("number of tags");
      }
      if (num_tags < 0) in_.fail_here("element " + std::to_string(number) + " has " + std::to_string(num_tags) + " tags");
      const ElementType& t = element_type(type, number);
      int physical = 0;
      for (std::int64_t k = 0; k < num_tags; ++k) {
        const std::int64_t tag = msh_.integer("element tag");
        if (k == 0) physical = tag_from_file(name_, in_.where(), "physical tag", tag);
      }
      read_element(type, t, number, physical);
      if (in_.binary()) --left_in_block;
    }
  }

  void reserve_elements(std::uint64_t announced, std::size_t min_bytes_each) {
    const std::size_t count = capped_count(announced, in_.bytes_left(), min_bytes_each);
    content_.tets.reserve(count);
    content_.tet_regions.reserve(count);
    tet_tags_.reserve(count);
  }

  const std::string& name_;
  MshSource msh_;
  FileCursor& in_;
  Version version_ = Version::V2;
  NodeTags nodes_;
  std::vector<std::uint64_t> tet_tags_, triangle_tags_;  // element tags, to sort the elements by
  bool nodes_read_ = false, elements_read_ = false;
  std::map<std::pair<std::int64_t, std::int64_t>, int> physical_of_;  // (dimension, entity) -> physical tag
  std::set<std::pair<std::int64_t, std::int64_t>> declared_entities_;  // (dimension, entity) in $Entities
  TetFileContent content_;
};

}  // namespace

TetFileContent read_gmsh(const std::string& name, std::string_view data) { return GmshReader(name, data).read(); }

}  // namespace meshprep::detail
