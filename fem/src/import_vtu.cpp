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
// Only what a tet mesh needs is read: the points, the cells' connectivity, offsets and types, and
// a region array among the cell data (vtk_cells.h); everything else is skipped unread.
#include "importers.h"
#include "vtk_cells.h"
#include "vtu_blocks.h"
#include "xml_scanner.h"

#include "readers.h"
#include "text_scanner.h"

#include <optional>
#include <utility>

namespace meshprep::detail {
namespace {

struct DataArray {
  std::string_view name, type, format;
  std::uint64_t components = 1;
  std::uint64_t offset = 0;  // appended only
  std::string_view text;     // ascii and binary only
  std::size_t tag_offset = 0;
};

struct Piece {
  std::uint64_t num_points = 0, num_cells = 0;
  std::optional<DataArray> points, connectivity, offsets, types, region;
  int region_rank = 0;  // region_array_rank of `region`
  std::size_t tag_offset = 0;
};

enum class Container { None, Points, Cells, CellData, Other };

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

class VtuReader {
 public:
  VtuReader(const std::string& name, std::string_view data) : name_(name), data_(data), xml_(name, data) {}

  TetFileContent read() {
    read_structure();
    if (pieces_.empty()) fail(name_, "no <Piece> in the <UnstructuredGrid>");
    for (const Piece& piece : pieces_) read_piece(piece);
    content_.format = "vtu " + format_name_ + (block_.zlib ? " zlib" : "");
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

  void add_array(Piece& piece, Container container, const XmlTag& tag) {
    DataArray array;
    array.name = tag.attribute("Name").value_or("");
    array.type = tag.attribute("type").value_or("");
    array.format = tag.attribute("format").value_or("ascii");
    array.components = number_attribute(tag, "NumberOfComponents", 1);
    array.offset = number_attribute(tag, "offset", 0);
    array.tag_offset = tag.begin;
    if (!tag.self_closing) array.text = data_.substr(tag.end, data_.find('<', tag.end) - tag.end);
    if (container == Container::Points) {
      if (!piece.points) piece.points = array;
    } else if (container == Container::Cells) {
      if (array.name == "connectivity") piece.connectivity = array;
      if (array.name == "offsets") piece.offsets = array;
      if (array.name == "types") piece.types = array;
    } else if (container == Container::CellData) {
      const int rank = region_array_rank(array.name);
      if (rank >= 0 && (!piece.region || rank < piece.region_rank)) {
        piece.region = array;
        piece.region_rank = rank;
      }
    }
  }

  // The tags up to <AppendedData> (after it, raw data may hold anything).
  void read_structure() {
    XmlTag tag;
    if (!xml_.next(0, tag)) fail(name_, "not a VTK XML file (no tags)");
    read_file_attributes(tag);
    Container container = Container::None;
    Piece* piece = nullptr;
    while (xml_.next(tag.end, tag)) {
      if (tag.name == "AppendedData" && !tag.closing) {
        read_appended_start(tag);
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
      } else if (tag.name == "Points" || tag.name == "Cells" || tag.name == "CellData" || tag.name == "PointData") {
        container = tag.closing || tag.self_closing ? Container::None
                    : tag.name == "Points"          ? Container::Points
                    : tag.name == "Cells"           ? Container::Cells
                    : tag.name == "CellData"        ? Container::CellData
                                                    : Container::Other;
      } else if (tag.name == "DataArray" && !tag.closing && piece) {
        add_array(*piece, container, tag);
      }
    }
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

  const std::string& name_;
  std::string_view data_;
  XmlScanner xml_;
  BlockFormat block_;
  std::vector<Piece> pieces_;
  bool has_appended_ = false, appended_base64_ = false;
  std::string_view appended_;
  std::string format_name_;
  TetFileContent content_;
};

}  // namespace

TetFileContent read_vtu(const std::string& name, std::string_view data) { return VtuReader(name, data).read(); }

}  // namespace meshprep::detail
