#pragma once
/// \file ply_header.h
/// The header of a PLY file: its format and the elements, with their properties, that the data
/// section holds in order.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace meshprep::detail {

/// The scalar types of PLY (char/int8 ... double/float64).
enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

/// One property of an element: a scalar or a list (a count, then that many items).
struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  ///< the value type; for a list, the item type
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;  ///< for a list, the type of its count (an integer type)
};

/// An element ("vertex", "face", ...): `count` instances, each holding every property in order.
struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

/// A parsed PLY header.
struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::size_t data_offset = 0;  ///< first byte after "end_header\n"
  std::size_t data_line = 0;    ///< number of the line that starts at data_offset
  std::vector<std::string> comments;  ///< the text after each `comment` keyword, in order
};

/// Bytes of a binary value of `type`.
std::size_t size_of(PlyType type);

/// Whether `type` is an integer type.
bool is_integral(PlyType type);

/// Whether an integer read from ASCII data fits the declared integer type.
bool fits(PlyType type, std::int64_t value);

/// Parses the header at the start of `data` (the content of `path`).
/// \throws InvalidInput on a malformed or unterminated header.
PlyHeader parse_ply_header(const std::string& path, std::string_view data);

}  // namespace meshprep::detail
