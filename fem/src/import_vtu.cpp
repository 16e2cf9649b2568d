// VTK XML UnstructuredGrid reader, .vtu ("VTK File Formats", section "XML File Formats";
// https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html).
//
// A data array's values are stored as format="ascii" (text), "binary" (base64 inside the element)
// or "appended" (at the array's offset in <AppendedData>, raw bytes or base64 as its encoding
// says; the data starts after the '_' that follows the tag). Binary data is a block: a header of
// header_type (UInt32 unless the file says UInt64) holding the data's byte count, then the data,
// in the file's byte_order. With compressor="vtkZLibDataCompressor" the header is [number of
// blocks, block size, size of the last block (0 = a full block), compressed size of each block]
// and the zlib-compressed blocks follow. VTK base64-encodes a header and its data as two streams,
// one after the other (so padding may end the header's), meshio as one when uncompressed:
// decoding four characters at a time, with padding allowed in any group, reads both.
//
// Only what a tet mesh needs is read: the points, the cells' connectivity, offsets and types, a
// region array among the cell data (vtk_cells.h), the point data "mesh_point_id" and the tag names
// of the FieldData (one integer array [tag, dimension] per name, export_vtu.cpp); everything else
// is skipped unread.
//
// A file x.vtu is read with the x_boundary.vtu beside it, when that is meshprep's boundary-faces
// file (it has the point data "mesh_point_id"): its triangles, on x.vtu's points through
// mesh_point_id, with their "patch" tags and its names (read_vtu_file). Each of its points must be
// where the x.vtu point it names is: a boundary file of another mesh is refused, not mixed in.
#include "importers.h"
#include "vtk_cells.h"
#include "vtu_blocks.h"
#include "vtu_files.h"
#include "xml_scanner.h"

#include "meshprep/core/io.h"
#include "meshprep/core/patch_names.h"

#include "readers.h"
#include "text_scanner.h"

#include <cmath>
#include <filesystem>
#include <optional>
#include <utility>

namespace meshprep::detail {
namespace {

struct DataArray {
  std::string_view name, type, format;
  std::uint64_t components = 1;
  std::uint64_t tuples = 1;  // field data only
  std::uint64_t offset = 0;  // appended only
  std::string_view text;     // ascii and binary only
  std::size_t tag_offset = 0;
};

struct Piece {
  std::uint64_t num_points = 0, num_cells = 0;
  std::optional<DataArray> points, connectivity, offsets, types, region, mesh_point_id;
  int region_rank = 0;  // region_array_rank of `region`
  std::size_t tag_offset = 0;
};

enum class Container { None, Points, Cells, CellData, PointData, FieldData, Other };

std::optional<VtkType> vtk_type(std::string_view name) {
  const std::pair<std::string_view, VtkType> types[] = {
      {"Int8", VtkType::Int8},       {"UInt8", VtkType::UInt8},     {"Int16", VtkType::Int16},
      {"UInt16", VtkType::UInt16},   {"Int32", VtkType::Int32},     {"UInt32", VtkType::UInt32},
      {"Int64", VtkType::Int64},     {"UInt64", VtkType::UInt64},   {"Float32", VtkType::Float32},
      {"Float64", VtkType::Float64},
  };
  for (const auto& [n, type] : types)
    if (n == name) return type;
  return std::nullopt;
}

// What a file holds besides the mesh: each point's mesh_point_id (when every piece has them).
struct VtuExtras {
  std::optional<std::vector<double>> mesh_point_ids;
};

class VtuReader {
 public:
  VtuReader(const std::string& name, std::string_view data) : name_(name), data_(data), xml_(name, data) {}

  TetFileContent read(VtuExtras* extras = nullptr) {
    read_structure();
    if (pieces_.empty()) fail(name_, "no <Piece> in the <UnstructuredGrid>");
    for (const Piece& piece : pieces_) read_piece(piece);
    read_tag_names();
    content_.format = "vtu " + format_name_ + (block_.zlib ? " zlib" : "");
    if (extras && every_piece_has_ids_) extras->mesh_point_ids = std::move(mesh_point_ids_);
    return std::move(content_);
  }

 private:
  std::uint64_t number_attribute(const XmlTag& tag, std::string_view key, std::uint64_t fallback) const {
    const std::optional<std::string_view> text = tag.attribute(key);
    if (!text) return fallback;
    std::int64_t value = 0;
    if (!parse_int(*text, value) || value < 0)
      xml_.fail_at(tag.begin, std::string(key) + "=" + quoted(*text) + " is not a count");
    return static_cast<std::uint64_t>(value);
  }

  void read_file_attributes(const XmlTag& tag) {
    if (tag.name != "VTKFile") xml_.fail_at(tag.begin, "not a VTK XML file (the first tag is <" + std::string(tag.name) + ">)");
    const std::string_view type = tag.attribute("type").value_or("");
    if (type != "UnstructuredGrid")
      xml_.fail_at(tag.begin, "VTKFile type " + quoted(type) + ": only UnstructuredGrid (.vtu) holds tetrahedra");
    const std::string_view order = tag.attribute("byte_order").value_or("LittleEndian");
    if (order != "LittleEndian" && order != "BigEndian") xml_.fail_at(tag.begin, "byte_order " + quoted(order));
    block_.little_endian = order == "LittleEndian";
    const std::string_view header = tag.attribute("header_type").value_or("UInt32");
    if (header != "UInt32" && header != "UInt64") xml_.fail_at(tag.begin, "header_type " + quoted(header) + " (UInt32 or UInt64)");
    block_.header_64 = header == "UInt64";
    const std::string_view compressor = tag.attribute("compressor").value_or("");
    if (!compressor.empty() && compressor != "vtkZLibDataCompressor")
      xml_.fail_at(tag.begin, "compressor " + quoted(compressor) + " is not supported (vtkZLibDataCompressor is)");
    block_.zlib = !compressor.empty();
  }

  DataArray data_array(const XmlTag& tag) const {
    DataArray array;
    array.name = tag.attribute("Name").value_or("");
    array.type = tag.attribute("type").value_or("");
    array.format = tag.attribute("format").value_or("ascii");
    array.components = number_attribute(tag, "NumberOfComponents", 1);
    array.tuples = number_attribute(tag, "NumberOfTuples", 1);
    array.offset = number_attribute(tag, "offset", 0);
    array.tag_offset = tag.begin;
    if (!tag.self_closing) array.text = data_.substr(tag.end, data_.find('<', tag.end) - tag.end);
    return array;
  }

  void add_array(Piece& piece, Container container, const XmlTag& tag) {
    const DataArray array = data_array(tag);
    if (container == Container::Points) {
      if (!piece.points) piece.points = array;
    } else if (container == Container::Cells) {
      if (array.name == "connectivity") piece.connectivity = array;
      if (array.name == "offsets") piece.offsets = array;
      if (array.name == "types") piece.types = array;
    } else if (container == Container::PointData) {
      if (array.name == "mesh_point_id") piece.mesh_point_id = array;
    } else if (container == Container::CellData) {
      const int rank = region_array_rank(array.name);
      if (rank >= 0 && (!piece.region || rank < piece.region_rank)) {
        piece.region = array;
        piece.region_rank = rank;
      }
    }
  }

  // A FieldData array that may name a tag: two integer values, [tag, dimension].
  void add_field_array(const XmlTag& tag) {
    const DataArray array = data_array(tag);
    const std::optional<VtkType> type = vtk_type(array.type);
    if (type && *type != VtkType::Float32 && *type != VtkType::Float64 && array.components * array.tuples == 2)
      field_arrays_.push_back(array);
  }

  // The names of the FieldData: dimension 3 names a region, 2 a boundary tag; a default name
  // (region_<r>, boundary_<t>, which the writer gives a tag without one) names nothing.
  void read_tag_names() {
    for (const DataArray& array : field_arrays_) {
      const std::vector<double> values = decode(array, 2);
      const std::optional<int> tag = integral_tag(values[0]);
      if (!tag || *tag < 1 || (values[1] != 2 && values[1] != 3)) continue;
      const char* prefix = values[1] == 3 ? "region" : "boundary";
      const std::string name(array.name);
      if (name != tag_name({}, *tag, prefix)) (values[1] == 3 ? content_.region_names : content_.triangle_names)[*tag] = name;
    }
  }

  // The tags up to <AppendedData> (after it, raw data may hold anything).
  void read_structure() {
    XmlTag tag;
    if (!xml_.next(0, tag)) fail(name_, "not a VTK XML file (no tags)");
    read_file_attributes(tag);
    Container container = Container::None;
    Piece* piece = nullptr;
    bool grid_closed = false;
    while (xml_.next(tag.end, tag)) {
      if (tag.name == "UnstructuredGrid" && tag.closing) grid_closed = true;
      if (tag.name == "AppendedData" && !tag.closing) {
        if (!grid_closed) xml_.fail_at(tag.begin, "<AppendedData> inside the <UnstructuredGrid>, which is not closed");
        read_appended_start(tag);
        require_file_end();
        return;
      }
      if (tag.name == "VTKFile" && tag.closing) {
        if (!grid_closed) xml_.fail_at(tag.begin, "</VTKFile> before the <UnstructuredGrid> is closed");
        return;
      }
      if (tag.name == "Piece") {
        if (tag.closing) {
          piece = nullptr;
          continue;
        }
        pieces_.emplace_back();
        piece = &pieces_.back();
        piece->num_points = number_attribute(tag, "NumberOfPoints", 0);
        piece->num_cells = number_attribute(tag, "NumberOfCells", 0);
        piece->tag_offset = tag.begin;
      } else if (tag.name == "Points" || tag.name == "Cells" || tag.name == "CellData" || tag.name == "PointData" ||
                 tag.name == "FieldData") {
        container = tag.closing || tag.self_closing ? Container::None
                    : tag.name == "Points"          ? Container::Points
                    : tag.name == "Cells"           ? Container::Cells
                    : tag.name == "CellData"        ? Container::CellData
                    : tag.name == "PointData"       ? Container::PointData
                                                    : Container::FieldData;
      } else if (tag.name == "DataArray" && !tag.closing && container == Container::FieldData && !piece) {
        add_field_array(tag);
      } else if (tag.name == "DataArray" && !tag.closing && piece) {
        add_array(*piece, container, tag);
      }
    }
    // A file cut short can still hold whole pieces (a two-piece file cut after the first one read
    // as half the mesh, issue 45, item 12): the document must end.
    fail(name_, std::string("truncated: the file ends before ") + (grid_closed ? "</VTKFile>" : "</UnstructuredGrid>"));
  }

  // After raw appended data the tags cannot be scanned: the file must end with </VTKFile>.
  void require_file_end() const {
    const std::size_t last = data_.find_last_not_of(" \t\r\n");
    constexpr std::string_view kEnd = "</VTKFile>";
    if (last == std::string_view::npos || last + 1 < kEnd.size() || data_.substr(last + 1 - kEnd.size(), kEnd.size()) != kEnd)
      fail(name_, "truncated: the file does not end with </VTKFile> after its <AppendedData>");
  }

  void read_appended_start(const XmlTag& tag) {
    const std::string_view encoding = tag.attribute("encoding").value_or("");
    if (encoding != "raw" && encoding != "base64")
      xml_.fail_at(tag.begin, "AppendedData encoding " + quoted(encoding) + " (raw or base64)");
    const std::size_t underscore = data_.find('_', tag.end);
    if (underscore == std::string_view::npos) xml_.fail_at(tag.begin, "AppendedData without the '_' that starts the data");
    appended_base64_ = encoding == "base64";
    appended_ = data_.substr(underscore + 1);
    if (appended_base64_) appended_ = appended_.substr(0, appended_.find('<'));
    has_appended_ = true;
  }

  // The `count` values of `array`.
  std::vector<double> decode(const DataArray& array, std::uint64_t count) {
    const std::string what = "DataArray " + quoted(array.name) + ": ";
    const std::optional<VtkType> type = vtk_type(array.type);
    if (!type) xml_.fail_at(array.tag_offset, what + "type " + quoted(array.type) + " is not a number type");
    try {
      if (array.format == "ascii") return decode_ascii(array, count);
      std::string bytes;
      if (array.format == "binary") {
        ByteStream in(array.text, /*base64=*/true);
        bytes = read_block(in, block_);
      } else if (array.format == "appended") {
        if (!has_appended_) xml_.fail_at(array.tag_offset, what + "format \"appended\" but the file has no <AppendedData>");
        if (array.offset > appended_.size())
          xml_.fail_at(array.tag_offset, what + "offset " + std::to_string(array.offset) + " is past the appended data");
        ByteStream in(appended_.substr(array.offset), appended_base64_);
        bytes = read_block(in, block_);
      } else {
        xml_.fail_at(array.tag_offset, what + "format " + quoted(array.format) + " (ascii, binary or appended)");
      }
      const std::size_t size = size_of(*type);
      if (bytes.size() % size != 0 || bytes.size() / size != count)
        throw BadData{std::to_string(bytes.size()) + " bytes of data, but " + std::to_string(count) + " values of " +
                      std::string(array.type) + " are expected"};
      note_format(array.format == "appended" ? (appended_base64_ ? "appended base64" : "appended raw") : "binary");
      return load_values(bytes, *type, count, block_.little_endian);
    } catch (const BadData& e) {
      xml_.fail_at(array.tag_offset, what + e.problem);
    }
  }

  std::vector<double> decode_ascii(const DataArray& array, std::uint64_t count) {
    note_format("ascii");
    std::vector<double> values;
    values.reserve(capped_count(count, array.text.size(), 2));
    TextScanner in(array.text);
    while (in.seek_token()) {
      const std::string_view token = in.token();
      double value = 0;
      if (!parse_double(token, value)) throw BadData{quoted(token) + " is not a number"};
      if (values.size() == count) throw BadData{"more than the " + std::to_string(count) + " values expected"};
      values.push_back(value);
    }
    if (values.size() != count)
      throw BadData{std::to_string(values.size()) + " values, but " + std::to_string(count) + " are expected"};
    return values;
  }

  void note_format(const char* format) {
    if (format_name_.empty()) format_name_ = format;
  }

  const DataArray& required(const std::optional<DataArray>& array, const Piece& piece, const char* what) const {
    if (!array) xml_.fail_at(piece.tag_offset, std::string("the piece has no ") + what + " array");
    return *array;
  }

  void read_piece(const Piece& piece) {
    read_mesh_point_ids(piece);
    const std::size_t first_point = content_.points.size();
    if (piece.num_points > 0) {
      const DataArray& points = required(piece.points, piece, "Points");
      if (points.components != 3)
        xml_.fail_at(points.tag_offset, "the points have " + std::to_string(points.components) + " components, not 3");
      if (piece.num_points > std::numeric_limits<std::uint32_t>::max() - first_point)
        xml_.fail_at(piece.tag_offset, "NumberOfPoints " + std::to_string(piece.num_points) + " is too large");
      const std::vector<double> xyz = decode(points, 3 * piece.num_points);
      for (std::size_t p = 0; p < piece.num_points; ++p) content_.points.emplace_back(xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2]);
    }
    if (piece.num_cells == 0) return;
    VtkCells cells;
    cells.offsets = decode(required(piece.offsets, piece, "offsets"), piece.num_cells);
    cells.types = decode(required(piece.types, piece, "types"), piece.num_cells);
    const double connectivity_size = cells.offsets.back();
    if (!(connectivity_size >= 0 && connectivity_size <= static_cast<double>(data_.size()) * 8))
      xml_.fail_at(piece.offsets->tag_offset, "the last offset " + std::to_string(connectivity_size) + " is not a size");
    cells.connectivity =
        decode(required(piece.connectivity, piece, "connectivity"), static_cast<std::uint64_t>(connectivity_size));
    if (piece.region) cells.regions = decode(*piece.region, piece.num_cells);
    add_vtk_cells(content_, cells, first_point, static_cast<std::size_t>(piece.num_points), name_);
  }

  void read_mesh_point_ids(const Piece& piece) {
    if (!piece.mesh_point_id) {
      every_piece_has_ids_ = false;
      return;
    }
    if (piece.mesh_point_id->components != 1)
      xml_.fail_at(piece.mesh_point_id->tag_offset, "mesh_point_id has " + std::to_string(piece.mesh_point_id->components) +
                                                        " components, not 1");
    const std::vector<double> ids = decode(*piece.mesh_point_id, piece.num_points);
    mesh_point_ids_.insert(mesh_point_ids_.end(), ids.begin(), ids.end());
  }

  const std::string& name_;
  std::string_view data_;
  XmlScanner xml_;
  BlockFormat block_;
  std::vector<Piece> pieces_;
  bool has_appended_ = false, appended_base64_ = false;
  std::string_view appended_;
  std::string format_name_;
  std::vector<DataArray> field_arrays_;
  std::vector<double> mesh_point_ids_;
  bool every_piece_has_ids_ = true;
  TetFileContent content_;
};

// The boundary faces, tags and names of meshprep's boundary-faces file `path` added to `content`
// (x.vtu's, read from `mesh_name`). Returns false, adding nothing, when the file is not one
// (no mesh_point_id).
bool add_boundary_file(TetFileContent& content, const std::string& mesh_name, const std::string& path) {
  const std::string data = read_input_file(path);
  if (data.empty()) fail(path, "empty file");
  VtuExtras extras;
  TetFileContent boundary = VtuReader(path, data).read(&extras);
  if (!extras.mesh_point_ids) return false;
  if (!boundary.tets.empty())
    fail(path, std::to_string(boundary.tets.size()) + " tetrahedra: a boundary-faces file holds triangles only");
  const std::vector<double>& ids = *extras.mesh_point_ids;
  std::vector<std::uint32_t> to_mesh(ids.size());
  for (std::size_t p = 0; p < ids.size(); ++p) {
    const std::optional<int> id = integral_tag(ids[p]);
    if (!id || *id < 0 || static_cast<std::size_t>(*id) >= content.points.size())
      fail(path, "point #" + std::to_string(p + 1) + " has mesh_point_id " + number_text(ids[p]) + ", but " + mesh_name +
                     " has " + std::to_string(content.points.size()) + " points (numbered from 0)");
    to_mesh[p] = static_cast<std::uint32_t>(*id);
    if (boundary.points[p] != content.points[to_mesh[p]])
      fail(path, "point #" + std::to_string(p + 1) + " is not where point " + std::to_string(*id) + " of " + mesh_name +
                     " is: the boundary faces of another mesh?");
  }
  for (std::size_t f = 0; f < boundary.triangles.size(); ++f) {
    const Triangle& t = boundary.triangles[f];
    content.triangles.push_back({to_mesh[t[0]], to_mesh[t[1]], to_mesh[t[2]]});
    content.triangle_tags.push_back(boundary.triangle_tags[f]);
  }
  content.triangle_names.insert(boundary.triangle_names.begin(), boundary.triangle_names.end());
  content.elements_ignored += boundary.elements_ignored;
  return true;
}

}  // namespace

TetFileContent read_vtu(const std::string& name, std::string_view data) { return VtuReader(name, data).read(); }

TetMesh read_vtu_file(const std::string& path, TetReadReport* report) {
  const std::string data = read_input_file(path);
  if (data.empty()) fail(path, "empty file");
  TetFileContent content = read_vtu(path, data);
  const std::string boundary = vtu_boundary_path(path);
  std::error_code ec;
  if (std::filesystem::is_regular_file(boundary, ec) && add_boundary_file(content, path, boundary))
    content.format += " + " + std::filesystem::path(boundary).filename().string();
  return assemble_tet_mesh(std::move(content), path, report);
}

}  // namespace meshprep::detail
