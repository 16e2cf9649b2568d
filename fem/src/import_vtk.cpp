// VTK legacy reader, .vtk UNSTRUCTURED_GRID, versions 2.0-5.1, ASCII and BINARY ("VTK File
// Formats", section "Simple Legacy Formats"; https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html).
//
// Layout: "# vtk DataFile Version x.y", a title line, ASCII or BINARY, "DATASET UNSTRUCTURED_GRID",
// then keyword lines, each followed by its values. BINARY values are big-endian and start on the
// line after their keyword line. Up to 4.2 "CELLS n size" lists each cell as "k id_1 ... id_k";
// 5.1 writes "CELLS n_offsets n_connectivity" followed by an OFFSETS array (n + 1 values, from 0)
// and a CONNECTIVITY array. Keywords are case-insensitive, as in VTK's reader.
//
// Only POINTS, CELLS, CELL_TYPES and a region array in CELL_DATA (SCALARS or FIELD, see
// vtk_cells.h) are kept; every other attribute (POINT_DATA, VECTORS, LOOKUP_TABLE, METADATA, ...)
// is read past, so that binary data cannot be mistaken for keywords.
#include "importers.h"
#include "vtk_cells.h"

#include "file_cursor.h"
#include "readers.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>

namespace meshprep::detail {
namespace {

std::string lowercase(std::string_view text) {
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower;
}

std::optional<VtkType> legacy_type(std::string_view name) {
  const std::pair<const char*, VtkType> types[] = {
      {"char", VtkType::Int8},           {"unsigned_char", VtkType::UInt8},   {"short", VtkType::Int16},
      {"unsigned_short", VtkType::UInt16}, {"int", VtkType::Int32},           {"unsigned_int", VtkType::UInt32},
      {"long", VtkType::Int64},          {"unsigned_long", VtkType::UInt64},  {"vtkidtype", VtkType::Int64},
      {"float", VtkType::Float32},       {"double", VtkType::Float64},        {"vtktypeint8", VtkType::Int8},
      {"vtktypeuint8", VtkType::UInt8},  {"vtktypeint16", VtkType::Int16},    {"vtktypeuint16", VtkType::UInt16},
      {"vtktypeint32", VtkType::Int32},  {"vtktypeuint32", VtkType::UInt32},  {"vtktypeint64", VtkType::Int64},
      {"vtktypeuint64", VtkType::UInt64}, {"vtktypefloat32", VtkType::Float32}, {"vtktypefloat64", VtkType::Float64},
  };
  const std::string lower = lowercase(name);
  for (const auto& [n, type] : types)
    if (lower == n) return type;
  return std::nullopt;
}

enum class Attributes { None, OfPoints, OfCells };

class VtkLegacyReader {
 public:
  VtkLegacyReader(const std::string& name, std::string_view data) : name_(name), data_(data), in_(name, data) {}

  TetFileContent read() {
    read_header();
    while (!in_.at_end()) {
      const std::string_view keyword = in_.token();
      in_.set_context("the " + std::string(keyword) + " data");
      read_keyword(lowercase(keyword));
    }
    if (have_cells_ && !have_types_) fail(name_, "CELLS without CELL_TYPES");
    if (cells_.types.size() != cells_.offsets.size())
      fail(name_, "CELL_TYPES lists " + std::to_string(cells_.types.size()) + " cells, CELLS " +
                      std::to_string(cells_.offsets.size()));
    if (!region_.empty() && region_.size() != cells_.offsets.size())
      fail(name_, "the region array has " + std::to_string(region_.size()) + " values for " +
                      std::to_string(cells_.offsets.size()) + " cells");
    cells_.regions = std::move(region_);
    add_vtk_cells(content_, cells_, 0, content_.points.size(), name_);
    return std::move(content_);
  }

 private:
  void read_header() {
    const std::string_view magic = "# vtk DataFile Version";
    if (data_.substr(0, magic.size()) != magic) fail(name_, "not a legacy VTK file (no \"# vtk DataFile Version\" line)");
    in_.bytes(magic.size());
    const std::string_view version = in_.field("the version");
    version_ = in_.real_of(version, "version");
    if (!(version_ >= 1.0 && version_ <= 5.1)) in_.fail_here("version " + quoted(version) + " (1.0 to 5.1 are read)");
    in_.next_line();  // to the title
    in_.next_line();  // past it
    const std::string encoding = lowercase(in_.token());
    if (encoding != "ascii" && encoding != "binary") in_.fail_here("expected ASCII or BINARY, found " + quoted(encoding));
    content_.format = "vtk " + std::string(version) + " " + encoding;
    const std::string dataset = lowercase(in_.token());
    const std::string_view type = in_.token();
    if (dataset != "dataset") in_.fail_here("expected DATASET, found " + quoted(dataset));
    if (lowercase(type) != "unstructured_grid")
      in_.fail_here("DATASET " + quoted(type) + ": only UNSTRUCTURED_GRID holds tetrahedra");
    if (encoding == "binary") in_.set_binary(/*little_endian=*/false);
  }

  std::uint64_t count(const char* what) { return in_.count(what); }

  VtkType type_of(std::string_view name) {
    const std::optional<VtkType> type = legacy_type(name);
    if (!type) in_.fail_here("data type " + quoted(name) + " is not supported");
    return *type;
  }

  // `count` values of `type` after the keyword line; kept only if `keep` (else read past).
  std::vector<double> values(VtkType type, std::uint64_t count, bool keep) {
    if (in_.binary()) {
      in_.start_binary_data();
      const std::size_t size = size_of(type);
      if (count > in_.bytes_left() / size) in_.fail_truncated();
      const std::string_view bytes = in_.bytes(static_cast<std::size_t>(count) * size);
      return keep ? load_values(bytes, type, static_cast<std::size_t>(count), /*little_endian=*/false)
                  : std::vector<double>();
    }
    std::vector<double> out;
    if (keep) out.reserve(capped_count(count, in_.bytes_left(), 2));
    for (std::uint64_t i = 0; i < count; ++i) {
      const double value = in_.real("value");
      if (keep) out.push_back(value);
    }
    return out;
  }

  // An attribute's values, kept when they are a region array whose name ranks better than the
  // one found so far, else read past.
  void attribute_array(std::string_view name, VtkType type, std::uint64_t components, std::uint64_t tuples) {
    if (components != 0 && tuples > std::numeric_limits<std::uint64_t>::max() / components)
      in_.fail_here("array " + quoted(name) + " is too large");
    const int rank = region_array_rank(name);
    const bool region = attributes_ == Attributes::OfCells && components == 1 && tuples == attribute_count_ &&
                        rank >= 0 && rank < region_rank_;
    std::vector<double> data = values(type, components * tuples, region);
    if (!region) return;
    region_ = std::move(data);
    region_rank_ = rank;
  }

  void read_cells() {
    const std::uint64_t first = count("CELLS count");
    const std::uint64_t second = count("CELLS size");
    have_cells_ = true;
    if (version_ >= 5.1) {  // offsets then connectivity, each an array with its own type line
      const auto array = [&](const char* keyword, std::uint64_t n) {
        const std::string_view k = in_.token();
        if (lowercase(k) != lowercase(keyword)) in_.fail_here(std::string("expected ") + keyword + ", found " + quoted(k));
        return values(type_of(in_.token()), n, true);
      };
      std::vector<double> offsets = array("OFFSETS", first);
      cells_.connectivity = array("CONNECTIVITY", second);
      if (!offsets.empty()) {
        if (offsets.front() != 0) in_.fail_here("OFFSETS does not start at 0");
        offsets.erase(offsets.begin());
      }
      cells_.offsets = std::move(offsets);
      return;
    }
    // "k id_1 ... id_k" per cell.
    const std::vector<double> list = values(VtkType::Int32, second, true);
    cells_.offsets.reserve(capped_count(first, list.size(), 1));
    cells_.connectivity.reserve(list.size());
    std::size_t pos = 0;
    for (std::uint64_t c = 0; c < first; ++c) {
      if (pos >= list.size()) fail(name_, "CELLS announces " + std::to_string(first) + " cells, its list holds " + std::to_string(c));
      const double k = list[pos];
      if (!(k >= 0 && k < static_cast<double>(list.size() - pos)))
        fail(name_, "CELLS: cell " + std::to_string(c) + " has " + std::to_string(k) + " points, past the list's end");
      const auto corners = static_cast<std::size_t>(k);
      cells_.connectivity.insert(cells_.connectivity.end(), list.begin() + static_cast<std::ptrdiff_t>(pos + 1),
                                 list.begin() + static_cast<std::ptrdiff_t>(pos + 1 + corners));
      cells_.offsets.push_back(static_cast<double>(cells_.connectivity.size()));
      pos += 1 + corners;
    }
    if (pos != list.size())
      fail(name_, "CELLS announces " + std::to_string(second) + " values, its " + std::to_string(first) + " cells use " +
                      std::to_string(pos));
  }

  void read_keyword(const std::string& keyword) {
    if (keyword == "points") {
      const std::uint64_t n = count("POINTS count");
      if (n > std::numeric_limits<std::uint32_t>::max()) in_.fail_here("too many points (" + std::to_string(n) + ")");
      const std::vector<double> xyz = values(type_of(in_.token()), 3 * n, true);
      content_.points.reserve(static_cast<std::size_t>(n));
      for (std::size_t p = 0; p < n; ++p) content_.points.emplace_back(xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2]);
    } else if (keyword == "cells") {
      read_cells();
    } else if (keyword == "cell_types") {
      cells_.types = values(VtkType::Int32, count("CELL_TYPES count"), true);
      have_types_ = true;
    } else if (keyword == "cell_data" || keyword == "point_data") {
      attributes_ = keyword == "cell_data" ? Attributes::OfCells : Attributes::OfPoints;
      attribute_count_ = count("attribute count");
    } else if (keyword == "scalars") {
      const std::string_view name = in_.token();
      const VtkType type = type_of(in_.token());
      const std::uint64_t components = in_.at_line_end() ? 1 : count("SCALARS components");
      if (in_.next_line_starts_with("LOOKUP_TABLE")) {
        in_.token();
        in_.token();  // its name
      }
      attribute_array(name, type, components, attribute_count_);
    } else if (keyword == "color_scalars") {  // unsigned char in BINARY, floats in ASCII
      in_.token();
      attribute_array("", VtkType::UInt8, count("COLOR_SCALARS components"), attribute_count_);
    } else if (keyword == "lookup_table") {  // RGBA per entry
      in_.token();
      attribute_array("", VtkType::UInt8, 4, count("LOOKUP_TABLE size"));
    } else if (keyword == "vectors" || keyword == "normals" || keyword == "tensors" || keyword == "tensors6" ||
               keyword == "global_ids" || keyword == "pedigree_ids") {
      const std::string_view name = in_.token();
      const std::uint64_t components = keyword == "tensors" ? 9 : keyword == "tensors6" ? 6 : keyword[0] == 'g' || keyword[0] == 'p' ? 1 : 3;
      attribute_array(name, type_of(in_.token()), components, attribute_count_);
    } else if (keyword == "texture_coordinates") {
      const std::string_view name = in_.token();
      const std::uint64_t dimension = count("TEXTURE_COORDINATES dimension");
      attribute_array(name, type_of(in_.token()), dimension, attribute_count_);
    } else if (keyword == "field") {
      in_.token();
      const std::uint64_t arrays = count("FIELD array count");
      for (std::uint64_t a = 0; a < arrays; ++a) read_field_array();
    } else if (keyword == "metadata") {
      in_.skip_to_blank_line();
    } else {
      in_.fail_here("unknown keyword " + quoted(keyword));
    }
  }

  // "name components tuples type" then the values (a NULL_ARRAY has none); 5.1 may put a
  // METADATA block after an array.
  void read_field_array() {
    std::string_view name = in_.token();
    for (; lowercase(name) == "metadata"; name = in_.token()) in_.skip_to_blank_line();
    if (name == "NULL_ARRAY") return;
    const std::uint64_t components = count("field array components");
    const std::uint64_t tuples = count("field array tuples");
    attribute_array(name, type_of(in_.token()), components, tuples);
  }

  const std::string& name_;
  std::string_view data_;
  FileCursor in_;
  double version_ = 0;
  bool have_cells_ = false, have_types_ = false;
  VtkCells cells_;
  Attributes attributes_ = Attributes::None;
  std::uint64_t attribute_count_ = 0;
  std::vector<double> region_;
  int region_rank_ = std::numeric_limits<int>::max();
  TetFileContent content_;
};

}  // namespace

TetFileContent read_vtk_legacy(const std::string& name, std::string_view data) {
  return VtkLegacyReader(name, data).read();
}

}  // namespace meshprep::detail
