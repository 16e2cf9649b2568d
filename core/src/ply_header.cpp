// PLY header parsing: format, elements and their properties, and where the data starts.
#include "ply_header.h"

#include "readers.h"
#include "text_scanner.h"

#include <limits>
#include <optional>

namespace meshprep::detail {
namespace {

std::optional<PlyType> type_named(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType::Int8;
  if (name == "uchar" || name == "uint8") return PlyType::UInt8;
  if (name == "short" || name == "int16") return PlyType::Int16;
  if (name == "ushort" || name == "uint16") return PlyType::UInt16;
  if (name == "int" || name == "int32") return PlyType::Int32;
  if (name == "uint" || name == "uint32") return PlyType::UInt32;
  if (name == "float" || name == "float32") return PlyType::Float32;
  if (name == "double" || name == "float64") return PlyType::Float64;
  return std::nullopt;
}

std::optional<PlyFormat> format_named(std::string_view name) {
  if (name == "ascii") return PlyFormat::Ascii;
  if (name == "binary_little_endian") return PlyFormat::BinaryLittleEndian;
  if (name == "binary_big_endian") return PlyFormat::BinaryBigEndian;
  return std::nullopt;
}

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  TextScanner in(line);
  for (std::string_view word = in.token(); !word.empty(); word = in.token()) words.push_back(word);
  return words;
}

}  // namespace

std::size_t size_of(PlyType type) {
  switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 8;
}

bool is_integral(PlyType type) { return type != PlyType::Float32 && type != PlyType::Float64; }

bool fits(PlyType type, std::int64_t value) {
  const auto in = [value](auto lowest, auto highest) { return value >= lowest && value <= highest; };
  switch (type) {
    case PlyType::Int8:
      return in(-128, 127);
    case PlyType::UInt8:
      return in(0, 255);
    case PlyType::Int16:
      return in(-32768, 32767);
    case PlyType::UInt16:
      return in(0, 65535);
    case PlyType::Int32:
      return in(std::int64_t{std::numeric_limits<std::int32_t>::min()},
                std::int64_t{std::numeric_limits<std::int32_t>::max()});
    case PlyType::UInt32:
      return in(std::int64_t{0}, std::int64_t{std::numeric_limits<std::uint32_t>::max()});
    default:
      return true;
  }
}

PlyHeader parse_ply_header(const std::string& path, std::string_view data) {
  PlyHeader header;
  bool has_format = false;
  std::size_t offset = 0;
  for (std::size_t line_number = 1;; ++line_number) {
    const std::size_t newline = data.find('\n', offset);
    if (newline == std::string_view::npos) fail(path, "truncated header (no end_header line)");
    const std::string_view line = data.substr(offset, newline - offset);
    const std::vector<std::string_view> words = split_words(line);
    offset = newline + 1;
    const auto fail_here = [&](const std::string& problem) { fail(path, at_line(line_number) + problem); };
    const std::string_view keyword = words.empty() ? std::string_view() : words[0];

    if (line_number == 1) {
      if (keyword != "ply" || words.size() != 1) fail(path, "not a PLY file (the first line is not 'ply')");
    } else if (keyword == "format") {
      if (words.size() != 3) fail_here("expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
      const std::optional<PlyFormat> format = format_named(words[1]);
      if (!format) fail_here("unknown format " + quoted(words[1]));
      header.format = *format;
      has_format = true;
    } else if (keyword == "element") {
      std::int64_t count = 0;
      if (words.size() != 3 || !parse_int(words[2], count) || count < 0) fail_here("expected 'element <name> <count>'");
      header.elements.push_back({std::string(words[1]), static_cast<std::uint64_t>(count), {}});
    } else if (keyword == "property") {
      if (header.elements.empty()) fail_here("property before any element");
      PlyProperty property;
      const bool is_list = words.size() == 5 && words[1] == "list";
      if (!is_list && words.size() != 3) {
        fail_here("expected 'property <type> <name>' or 'property list <type> <type> <name>'");
      }
      const std::string_view type_word = words[is_list ? 3 : 1];
      const std::optional<PlyType> type = type_named(type_word);
      if (!type) fail_here("unknown property type " + quoted(type_word));
      property.type = *type;
      property.is_list = is_list;
      if (is_list) {
        const std::optional<PlyType> count_type = type_named(words[2]);
        if (!count_type || !is_integral(*count_type)) {
          fail_here("list count type " + quoted(words[2]) + " is not an integer type");
        }
        property.count_type = *count_type;
      }
      property.name = std::string(words.back());
      header.elements.back().properties.push_back(property);
    } else if (keyword == "end_header") {
      if (!has_format) fail(path, "the header has no format line");
      header.data_offset = offset;
      header.data_line = line_number + 1;
      return header;
    } else if (keyword == "comment") {
      std::string_view text = line.substr(line.find("comment") + 7);
      while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
      while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) text.remove_suffix(1);
      header.comments.emplace_back(text);
    } else if (keyword != "obj_info" && !keyword.empty()) {
      fail_here("unknown header keyword " + quoted(keyword));
    }
  }
}

}  // namespace meshprep::detail
