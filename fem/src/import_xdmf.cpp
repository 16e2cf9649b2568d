// XDMF reader, .xdmf: XML light data whose DataItems hold their values inline (Format="XML") or
// name them in an HDF5 file (Format="HDF", "x.h5:/Mesh/mesh/topology", the file relative to the
// .xdmf's folder). The XDMF model: https://www.xdmf.org/index.php/XDMF_Model_and_Format; what
// dolfinx writes and reads: dolfinx 0.5, cpp/dolfinx/io/XDMFFile.cpp (read_mesh, read_meshtags)
// and xdmf_utils.cpp (get_dataset), and export_xdmf.cpp here.
//
// What is read, from the Uniform grids directly under /Xdmf/Domain (where dolfinx looks):
// - the mesh: the grid named "mesh" (dolfinx's default name), else the first grid with a Geometry
//   of its own. Its Topology must be "Tetrahedron" (4 nodes per cell, 0-based point indices) or
//   "Tetrahedron_10" (the corners, then the nodes of edges (0,1) (1,2) (2,0) (0,3) (1,3) (2,3): VTK's
//   order, which dolfinx's XDMF files and meshio's use; then the tag grids' are "Triangle_6" and
//   "Tetrahedron_10"), its
//   Geometry "XYZ" (one N x 3 DataItem). Its regions: a cell-centred Attribute named like a VTK
//   region array (region, gmsh:physical, ...: vtk_cells.h; what meshio writes), unless a
//   "cell_tags" grid gives them.
// - boundary tags: the grid named "facet_tags", else the first other grid with a "Triangle"
//   topology and a cell-centred Attribute; its triangles index the mesh's points (dolfinx writes
//   them so) and become the file's triangles, as in the other formats.
// - regions: the grid named "cell_tags", else the first other grid with a "Tetrahedron" topology
//   and a cell-centred Attribute; each tagged tet is found among the mesh's by its corners (dolfinx
//   does the same: it may order the two differently).
// - names: each tag grid's <Information Name="<name>" Value="<tag>"/> (export_xdmf.cpp). A default
//   name ("boundary_3" for tag 3) is dropped: a mesh without names reads back without. The names
//   of tags the mesh has are kept, made to follow the naming rule (assemble_tet_mesh).
// Other grids (a dolfinx grid of edge tags, a second mesh) are skipped. Grid collections (time
// series), HyperSlab and Function DataItems, Format="Binary" and mixed topologies are refused.
#include "hdf5_file.h"
#include "importers.h"
#include "vtk_cells.h"
#include "xml_scanner.h"

#include "meshprep/core/patch_names.h"
#include "readers.h"
#include "text_scanner.h"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <tuple>

namespace meshprep::detail {
namespace {

namespace fs = std::filesystem;

// An XML element: its tag's name and attributes, the text right after its start tag (a DataItem's
// values or reference), and its children (indices into the element list).
struct Element {
  std::string_view name;
  std::vector<std::pair<std::string_view, std::string_view>> attributes;
  std::string_view text;
  std::vector<std::size_t> children;
  std::size_t offset = 0;  // of its '<'

  std::optional<std::string_view> attribute(std::string_view key) const {
    for (const auto& [k, v] : attributes)
      if (k == key) return v;
    return std::nullopt;
  }
};

// "line N" of the byte at `offset`.
std::string line_of(std::string_view data, std::size_t offset) {
  return "line " + std::to_string(std::count(data.begin(), data.begin() + static_cast<std::ptrdiff_t>(offset), '\n') + 1);
}

// The elements of the document; element 0 stands for the document itself.
std::vector<Element> parse_elements(const XmlScanner& xml, std::string_view data) {
  std::vector<Element> elements(1);
  std::vector<std::size_t> open{0};
  XmlTag tag;
  for (std::size_t at = 0; xml.next(at, tag); at = tag.end) {
    if (tag.closing) {
      const std::string closing = "</" + std::string(tag.name) + ">";
      if (open.size() == 1) xml.fail_at(tag.begin, closing + " without its start tag");
      const Element& innermost = elements[open.back()];
      if (innermost.name != tag.name)
        xml.fail_at(tag.begin, closing + " found where <" + std::string(innermost.name) + "> (" +
                                   line_of(data, innermost.offset) + ") is open");
      open.pop_back();
      continue;
    }
    Element element;
    element.name = tag.name;
    element.attributes = tag.attributes;
    element.offset = tag.begin;
    if (!tag.self_closing) {
      const std::size_t next = std::min(data.find('<', tag.end), data.size());
      element.text = data.substr(tag.end, next - tag.end);
    }
    elements[open.back()].children.push_back(elements.size());
    if (!tag.self_closing) open.push_back(elements.size());
    elements.push_back(std::move(element));
  }
  if (open.size() > 1) xml.fail_at(elements[open.back()].offset, "<" + std::string(elements[open.back()].name) + "> is not closed");
  return elements;
}

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

// The text with XML's five predefined entities and the decimal character references of ASCII
// characters ("&#39;", what html::escape writes for ') replaced: a file name may hold '&'.
std::string unescaped(std::string_view text) {
  static const std::pair<std::string_view, char> entities[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    bool replaced = false;
    for (const auto& [entity, c] : entities)
      if (text.substr(i, entity.size()) == entity) {
        out += c;
        i += entity.size();
        replaced = true;
        break;
      }
    const std::size_t end = text.find(';', i);
    std::int64_t code = 0;
    if (!replaced && text.substr(i, 2) == "&#" && end != std::string_view::npos &&
        parse_int(text.substr(i + 2, end - i - 2), code) && code > 0 && code < 128) {
      out += static_cast<char>(code);
      i = end + 1;
      replaced = true;
    }
    if (!replaced) out += text[i++];
  }
  return out;
}

std::string shape_text(const std::vector<std::uint64_t>& dims) {
  std::string text;
  for (const std::uint64_t d : dims) text += (text.empty() ? "" : " x ") + std::to_string(d);
  return text;
}

// The HDF5 files a document names, each opened once, read only.
class HeavyData {
 public:
  HeavyData(const std::string& name, const std::string& folder) : name_(name), folder_(folder) {}

  // The values of `dataset` in `file`, which must have the shape `dims`, as `memory_type` (HDF5
  // converts); `integers` refuses floating-point data. `where` starts the messages.
  template <class T>
  std::vector<T> read(const std::string& where, const std::string& file, const std::string& dataset,
                      const std::vector<std::uint64_t>& dims, hid_t memory_type, bool integers) {
    const std::string what = where + file + ":" + dataset + ": ";
    const Hdf5Handle set(H5Dopen2(open(where, file), dataset.c_str(), H5P_DEFAULT), H5Dclose);
    if (!set.valid()) fail(name_, what + "no such dataset in the HDF5 file");
    const Hdf5Handle space(H5Dget_space(set.get()), H5Sclose);
    const int rank = space.valid() ? H5Sget_simple_extent_ndims(space.get()) : -1;
    if (rank < 0 || rank > 8) fail(name_, what + "the dataset's shape cannot be read");
    hsize_t extent[8] = {};
    H5Sget_simple_extent_dims(space.get(), extent, nullptr);
    const std::vector<std::uint64_t> shape(extent, extent + rank);
    if (shape != dims)
      fail(name_, what + "the dataset holds " + shape_text(shape) + " values, its DataItem says " + shape_text(dims));
    const Hdf5Handle type(H5Dget_type(set.get()), H5Tclose);
    const H5T_class_t type_class = type.valid() ? H5Tget_class(type.get()) : H5T_NO_CLASS;
    if (type_class != H5T_INTEGER && (integers || type_class != H5T_FLOAT))
      fail(name_, what + (integers ? "not integer data" : "not numbers"));
    std::uint64_t count = 1;
    for (const std::uint64_t d : dims) count *= d;  // dims checked not to overflow (data_item_shape)
    if (count == 0) return {};
    // A dataset may announce more values than it stores (unwritten chunks read as fill values): no
    // more memory than its storage could hold, compressed at zlib's best ratio (~1:1032), is spent.
    const std::uint64_t stored = H5Dget_storage_size(set.get());
    const std::uint64_t element_size = H5Tget_size(type.get());
    if (stored / element_size < count / 1100)
      fail(name_, what + "the dataset announces " + std::to_string(count) + " values but stores " +
                      std::to_string(stored) + " bytes");
    std::vector<T> values(static_cast<std::size_t>(count));
    if (H5Dread(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
      fail(name_, what + "cannot be read (" + hdf5_reason() + ")");
    return values;
  }

 private:
  hid_t open(const std::string& where, const std::string& file) {
    const auto found = files_.find(file);
    if (found != files_.end()) return found->second->get();
    const fs::path path = fs::path(file).is_absolute() || folder_.empty() ? fs::path(file) : fs::path(folder_) / file;
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
      fail(name_, where + "the HDF5 file " + path.string() + " that holds the data " +
                      (fs::exists(path, ec) ? "is not a regular file" : "does not exist"));
    if (H5Fis_hdf5(path.c_str()) <= 0) fail(name_, where + path.string() + " is not an HDF5 file");
    auto handle = std::make_unique<Hdf5Handle>(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (!handle->valid()) fail(name_, where + "cannot open the HDF5 file " + path.string() + ": " + hdf5_reason());
    return files_.emplace(file, std::move(handle)).first->second->get();
  }

  const std::string& name_;
  std::string folder_;
  std::map<std::string, std::unique_ptr<Hdf5Handle>> files_;
};

// A grid's topology as the reader needs it.
struct Topology {
  const Element* element = nullptr;
  std::string_view type;
  std::size_t nodes = 0;  // per cell: 4, 10, 3 or 6; 0 for any other type
};

class XdmfReader {
 public:
  XdmfReader(const std::string& name, std::string_view data, const std::string& folder)
      : name_(name), data_(data), xml_(name, data), heavy_(name, folder) {}

  TetFileContent read() {
    const Hdf5Quiet quiet;
    elements_ = parse_elements(xml_, data_);
    const Element* root = child(elements_[0], "Xdmf");
    if (!root) fail(name_, "not an XDMF file (no <Xdmf> element)");
    const std::string_view version = root->attribute("Version").value_or("");
    if (!version.empty() && version[0] != '2' && version[0] != '3')
      xml_.fail_at(root->offset, "XDMF Version " + quoted(version) + " (2 and 3 are read)");
    const Element* domain = child(*root, "Domain");
    if (!domain) xml_.fail_at(root->offset, "no <Domain> in the <Xdmf> element");

    std::vector<const Element*> grids;
    for (const std::size_t c : domain->children) {
      const Element& grid = elements_[c];
      if (grid.name != "Grid") continue;
      const std::string_view type = grid.attribute("GridType").value_or("Uniform");
      if (type != "Uniform")
        xml_.fail_at(grid.offset, "GridType " + quoted(type) + ": only Uniform grids are read (not time series or collections)");
      grids.push_back(&grid);
    }
    const Element* mesh = find_mesh_grid(grids);
    if (!mesh) xml_.fail_at(domain->offset, "no <Grid> with a <Geometry> of its own (the mesh) in the <Domain>");
    read_mesh(*mesh);
    const bool second_order = !content_.tet_edge_nodes.empty();
    const Element* cell_tags = find_tag_grid(grids, mesh, "cell_tags", second_order ? 10 : 4);
    const Element* facet_tags = find_tag_grid(grids, mesh, "facet_tags", second_order ? 6 : 3);
    if (cell_tags) read_cell_tags(*cell_tags, second_order);
    if (facet_tags) read_facet_tags(*facet_tags, second_order);
    content_.format = "xdmf " + std::string(version.empty() ? "2" : version) + (used_hdf_ ? " hdf5" : " xml");
    return std::move(content_);
  }

 private:
  const Element* child(const Element& parent, std::string_view name) const {
    for (const std::size_t c : parent.children)
      if (elements_[c].name == name) return &elements_[c];
    return nullptr;
  }

  // "line N: ", the prefix of problems found at `element`.
  std::string where(const Element& element) const { return line_of(data_, element.offset) + ": "; }

  const Element* find_mesh_grid(const std::vector<const Element*>& grids) const {
    for (const Element* grid : grids)
      if (grid->attribute("Name") == std::string_view("mesh") && child(*grid, "Geometry")) return grid;
    for (const Element* grid : grids)
      if (child(*grid, "Geometry")) return grid;
    return nullptr;
  }

  Topology topology(const Element& grid) const {
    Topology t;
    t.element = child(grid, "Topology");
    if (!t.element) return t;
    // XDMF 3 names the attribute Type, XDMF 2 and dolfinx TopologyType.
    t.type = t.element->attribute("TopologyType").value_or(t.element->attribute("Type").value_or(""));
    t.nodes = t.type == "Tetrahedron" ? 4 : t.type == "Tetrahedron_10" ? 10 : t.type == "Triangle" ? 3 : t.type == "Triangle_6" ? 6 : 0;
    if (t.nodes != 0) {
      const std::optional<std::string_view> nodes = t.element->attribute("NodesPerElement");
      std::int64_t n = 0;
      if (nodes && (!parse_int(*nodes, n) || n != static_cast<std::int64_t>(t.nodes)))
        xml_.fail_at(t.element->offset, "a " + std::string(t.type) + " has " + std::to_string(t.nodes) +
                                            " nodes, not NodesPerElement=" + quoted(*nodes));
    }
    return t;
  }

  // The first cell-centred Attribute of `grid` (XDMF's default Center is Node).
  const Element* cell_attribute(const Element& grid, bool region_names_only) const {
    for (const std::size_t c : grid.children) {
      const Element& attribute = elements_[c];
      if (attribute.name != "Attribute" || attribute.attribute("Center").value_or("Node") != "Cell") continue;
      if (region_names_only && region_array_rank(attribute.attribute("Name").value_or("")) < 0) continue;
      return &attribute;
    }
    return nullptr;
  }

  const Element* find_tag_grid(const std::vector<const Element*>& grids, const Element* mesh, std::string_view name,
                               std::size_t nodes) const {
    for (const Element* grid : grids)
      if (grid != mesh && grid->attribute("Name") == name) return grid;
    for (const Element* grid : grids)
      if (grid != mesh && topology(*grid).nodes == nodes && cell_attribute(*grid, false)) return grid;
    return nullptr;
  }

  // ---- DataItems ----

  const Element& data_item(const Element& parent) const {
    const Element* item = child(parent, "DataItem");
    if (!item) xml_.fail_at(parent.offset, "<" + std::string(parent.name) + "> has no <DataItem>");
    const std::string_view type = item->attribute("ItemType").value_or("Uniform");
    if (type != "Uniform") xml_.fail_at(item->offset, "DataItem ItemType " + quoted(type) + " is not read (Uniform is)");
    return *item;
  }

  // The DataItem's Dimensions, checked to describe `columns` values per row: "rows columns" or
  // "rows*columns" (one dimension). Returns the dimensions and sets `rows`.
  std::vector<std::uint64_t> data_item_shape(const Element& item, std::size_t columns, std::size_t& rows) const {
    const std::optional<std::string_view> text = item.attribute("Dimensions");
    if (!text) xml_.fail_at(item.offset, "the DataItem has no Dimensions");
    std::vector<std::uint64_t> dims;
    TextScanner in(*text);
    while (in.seek_token()) {
      std::int64_t d = 0;
      if (!parse_int(in.token(), d) || d < 0 || d > std::numeric_limits<std::int32_t>::max() || dims.size() == 2)
        xml_.fail_at(item.offset, "Dimensions=" + quoted(*text) + " is not one or two sizes below 2^31");
      dims.push_back(static_cast<std::uint64_t>(d));
    }
    const bool fits = (dims.size() == 2 && dims[1] == columns) || (dims.size() == 1 && dims[0] % columns == 0);
    if (!fits)
      xml_.fail_at(item.offset, "Dimensions=" + quoted(*text) + ": expected N " + std::to_string(columns) + " values");
    rows = static_cast<std::size_t>(dims.size() == 2 ? dims[0] : dims[0] / columns);
    return dims;
  }

  // `columns` values per row of the DataItem of `parent`; `rows` is set. Integers are read as
  // int64, reals as double.
  template <class T>
  std::vector<T> values(const Element& parent, std::size_t columns, std::size_t& rows) {
    const Element& item = data_item(parent);
    const std::vector<std::uint64_t> dims = data_item_shape(item, columns, rows);
    const std::string_view format = item.attribute("Format").value_or("XML");
    constexpr bool integers = std::is_integral_v<T>;
    if (format == "HDF") {
      used_hdf_ = true;
      const std::string reference = unescaped(trimmed(item.text));
      const std::size_t colon = reference.rfind(":/");
      if (colon == std::string::npos || colon == 0)
        xml_.fail_at(item.offset, "the HDF DataItem " + quoted(std::string_view(reference)) + " is not FILE:/DATASET");
      return heavy_.read<T>(where(item), reference.substr(0, colon), reference.substr(colon + 1), dims,
                            integers ? H5T_NATIVE_INT64 : H5T_NATIVE_DOUBLE, integers);
    }
    if (format != "XML")
      xml_.fail_at(item.offset, "DataItem Format " + quoted(format) + " is not read (HDF and XML are)");
    const std::size_t count = rows * columns;
    std::vector<T> out;
    out.reserve(capped_count(count, item.text.size(), 2));
    TextScanner in(item.text);
    while (in.seek_token()) {
      const std::string_view token = in.token();
      if (out.size() == count)
        xml_.fail_at(item.offset, "the DataItem holds more than its " + std::to_string(count) + " values");
      if constexpr (integers) {
        std::int64_t v = 0;
        if (!parse_int(token, v)) xml_.fail_at(item.offset, "the DataItem's value " + quoted(token) + " is not an integer");
        out.push_back(v);
      } else {
        double v = 0;
        if (!parse_double(token, v)) xml_.fail_at(item.offset, "the DataItem's value " + quoted(token) + " is not a number");
        out.push_back(v);
      }
    }
    if (out.size() != count)
      xml_.fail_at(item.offset, "the DataItem holds " + std::to_string(out.size()) + " values, its Dimensions " +
                                    std::to_string(count));
    return out;
  }

  // The cells of a topology: N indices each, checked to be points of the mesh.
  template <std::size_t N>
  std::vector<std::array<std::uint32_t, N>> cells(const Topology& t, const char* element) {
    std::size_t rows = 0;
    const std::vector<std::int64_t> flat = values<std::int64_t>(*t.element, N, rows);
    const std::optional<std::string_view> declared = t.element->attribute("NumberOfElements");
    std::int64_t n = 0;
    if (declared && (!parse_int(*declared, n) || n != static_cast<std::int64_t>(rows)))
      xml_.fail_at(t.element->offset, "NumberOfElements=" + quoted(*declared) + ", but the DataItem holds " +
                                          std::to_string(rows) + " cells");
    const std::size_t num_points = content_.points.size();
    std::vector<std::array<std::uint32_t, N>> out(rows);
    for (std::size_t c = 0; c < rows; ++c)
      for (std::size_t k = 0; k < N; ++k) {
        const std::int64_t index = flat[c * N + k];
        if (!in_numbering(index, 0, num_points))
          fail_node_reference(name_, where(*t.element), element, c + 1, index, 0, num_points);
        out[c][k] = static_cast<std::uint32_t>(index);
      }
    return out;
  }

  // The values of a cell-centred Attribute, one per cell, as tags.
  std::vector<int> tags(const Element& attribute, std::size_t cells) {
    std::size_t rows = 0;
    const std::vector<double> flat = values<double>(attribute, 1, rows);
    if (rows != cells)
      xml_.fail_at(attribute.offset, "the Attribute has " + std::to_string(rows) + " values for " + std::to_string(cells) + " cells");
    std::vector<int> out(rows);
    for (std::size_t c = 0; c < rows; ++c) {
      const std::optional<int> tag = integral_tag(flat[c]);
      if (!tag) xml_.fail_at(attribute.offset, "the Attribute's value " + number_text(flat[c]) + " is not an integer tag");
      out[c] = *tag;
    }
    return out;
  }

  // ---- the grids ----

  void read_mesh(const Element& grid) {
    const Element& geometry = *child(grid, "Geometry");
    const std::string_view type = geometry.attribute("GeometryType").value_or(geometry.attribute("Type").value_or("XYZ"));
    if (type == "XY") xml_.fail_at(geometry.offset, "GeometryType XY: a tetrahedral mesh is 3D");
    if (type != "XYZ") xml_.fail_at(geometry.offset, "GeometryType " + quoted(type) + " is not read (XYZ is)");
    std::size_t rows = 0;
    const std::vector<double> xyz = values<double>(geometry, 3, rows);
    content_.points.resize(rows);
    for (std::size_t p = 0; p < rows; ++p) content_.points[p] = Vec3(xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2]);

    const Topology t = topology(grid);
    if (!t.element) xml_.fail_at(grid.offset, "the mesh's <Grid> has no <Topology>");
    if (t.nodes == 3) {
      content_.triangles = cells<3>(t, "triangle");
      content_.triangle_tags.assign(content_.triangles.size(), 0);
      return;  // a surface: assemble_tet_mesh says so
    }
    if (t.nodes == 10)
      split_nodes(cells<10>(t, "tetrahedron"), content_.tets, content_.tet_edge_nodes);
    else if (t.nodes == 4)
      content_.tets = cells<4>(t, "tetrahedron");
    else
      xml_.fail_at(t.element->offset, "TopologyType " + quoted(t.type) + ": meshprep reads Tetrahedron and Tetrahedron_10 only");
    content_.tet_regions.assign(content_.tets.size(), 0);
    if (const Element* regions = cell_attribute(grid, true)) content_.tet_regions = tags(*regions, content_.tets.size());
  }

  // The tag grid's topology and values, checked to be `nodes`-node cells.
  template <std::size_t N>
  std::pair<std::vector<std::array<std::uint32_t, N>>, std::vector<int>> tagged(const Element& grid, const char* element) {
    const Topology t = topology(grid);
    if (!t.element) xml_.fail_at(grid.offset, "the tag <Grid> has no <Topology>");
    if (t.nodes != N)
      xml_.fail_at(t.element->offset, "TopologyType " + quoted(t.type) + " in a grid of " + element + " tags");
    const Element* attribute = cell_attribute(grid, false);
    if (!attribute) xml_.fail_at(grid.offset, "the tag <Grid> has no <Attribute> with Center=\"Cell\"");
    auto entities = cells<N>(t, element);
    std::vector<int> values = tags(*attribute, entities.size());
    return {std::move(entities), std::move(values)};
  }

  void read_facet_tags(const Element& grid, bool second_order) {
    std::vector<int> values;
    if (second_order) {
      auto [triangles, tags] = tagged<6>(grid, "triangle");
      split_nodes(triangles, content_.triangles, content_.triangle_edge_nodes);
      values = std::move(tags);
    } else {
      auto [triangles, tags] = tagged<3>(grid, "triangle");
      content_.triangles.insert(content_.triangles.end(), triangles.begin(), triangles.end());
      values = std::move(tags);
    }
    content_.triangle_tags.insert(content_.triangle_tags.end(), values.begin(), values.end());
    content_.triangle_names = names(grid, "boundary");
  }

  // A second-order mesh's tagged tets are found by their corners: their mid-edge nodes are those
  // the mesh grid gives them.
  void read_cell_tags(const Element& grid, bool second_order) {
    std::vector<Tetrahedron> tets;
    std::vector<int> values;
    if (second_order) {
      auto [tets_10, tags] = tagged<10>(grid, "tetrahedron");
      std::vector<TetEdgeNodes> edge_nodes_as_in_the_mesh;
      split_nodes(tets_10, tets, edge_nodes_as_in_the_mesh);
      values = std::move(tags);
    } else {
      std::tie(tets, values) = tagged<4>(grid, "tetrahedron");
    }
    if (tets == content_.tets) {
      content_.tet_regions = std::move(values);  // what export_xdmf.cpp writes: the same tets
    } else {
      // Sorted corners -> tet, then each tagged tet looked up.
      std::vector<std::pair<Tetrahedron, std::size_t>> by_corners(content_.tets.size());
      for (std::size_t t = 0; t < content_.tets.size(); ++t) {
        by_corners[t] = {content_.tets[t], t};
        std::sort(by_corners[t].first.begin(), by_corners[t].first.end());
      }
      std::sort(by_corners.begin(), by_corners.end());
      std::vector<bool> seen(content_.tets.size(), false);
      for (std::size_t e = 0; e < tets.size(); ++e) {
        Tetrahedron key = tets[e];
        std::sort(key.begin(), key.end());
        const auto found = std::lower_bound(by_corners.begin(), by_corners.end(), std::make_pair(key, std::size_t{0}));
        if (found == by_corners.end() || found->first != key)
          xml_.fail_at(grid.offset, "tagged tetrahedron " + std::to_string(e + 1) + " (points " + std::to_string(tets[e][0]) +
                                        ", " + std::to_string(tets[e][1]) + ", " + std::to_string(tets[e][2]) + ", " +
                                        std::to_string(tets[e][3]) + ") is not a cell of the mesh");
        const std::size_t t = found->second;
        if (seen[t] && content_.tet_regions[t] != values[e])
          xml_.fail_at(grid.offset, "tetrahedron " + std::to_string(t + 1) + " is tagged twice (" +
                                        std::to_string(content_.tet_regions[t]) + " and " + std::to_string(values[e]) + ")");
        seen[t] = true;
        content_.tet_regions[t] = values[e];
      }
    }
    content_.region_names = names(grid, "region");
  }

  // The <Information Name="<name>" Value="<tag>"/> children of a tag grid, the default names left out.
  TagNames names(const Element& grid, const char* prefix) const {
    TagNames out;
    for (const std::size_t c : grid.children) {
      const Element& info = elements_[c];
      if (info.name != "Information") continue;
      std::int64_t tag = 0;
      if (!parse_int(info.attribute("Value").value_or(""), tag) || tag < 1 || tag > std::numeric_limits<int>::max())
        continue;  // not a tag's name (another program's information)
      // A name against the rule is made to follow it by assemble_tet_mesh (and reported there).
      const std::string name = unescaped(info.attribute("Name").value_or(""));
      const auto [it, added] = out.emplace(static_cast<int>(tag), name);
      if (!added) xml_.fail_at(info.offset, "tag " + std::to_string(tag) + " is named twice (" + it->second + ", " + name + ")");
    }
    for (auto it = out.begin(); it != out.end();)
      it = it->second == tag_name({}, it->first, prefix) ? out.erase(it) : std::next(it);
    return out;
  }

  const std::string& name_;
  std::string_view data_;
  XmlScanner xml_;
  HeavyData heavy_;
  std::vector<Element> elements_;
  TetFileContent content_;
  bool used_hdf_ = false;
};

}  // namespace

TetFileContent read_xdmf(const std::string& name, std::string_view data, const std::string& folder) {
  return XdmfReader(name, data, folder).read();
}

TetMesh read_xdmf_file(const std::string& path, TetReadReport* report) {
  const std::string data = read_input_file(path);
  if (data.empty()) fail(path, "empty file");
  return assemble_tet_mesh(read_xdmf(path, data, fs::path(path).parent_path().string()), path, report);
}

}  // namespace meshprep::detail
