#pragma once
/// \file byte_order.h
/// Loading and storing binary values of either byte order without unaligned access.

#include <algorithm>
#include <cstring>
#include <string>
#include <type_traits>

namespace meshprep::detail {

/// Whether this machine stores numbers little endian.
constexpr bool host_is_little_endian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;

/// The value of type T stored at `bytes` (which need not be aligned) in the given byte order.
template <class T>
T load_value(const char* bytes, bool little_endian) {
  static_assert(std::is_arithmetic_v<T>);
  char copy[sizeof(T)];
  std::memcpy(copy, bytes, sizeof(T));
  if (little_endian != host_is_little_endian) std::reverse(copy, copy + sizeof(T));
  T value;
  std::memcpy(&value, copy, sizeof(T));
  return value;
}

/// Appends `value` to `out` in little-endian byte order.
template <class T>
void append_little_endian(std::string& out, T value) {
  static_assert(std::is_arithmetic_v<T>);
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (!host_is_little_endian) std::reverse(bytes, bytes + sizeof(T));
  out.append(bytes, sizeof(T));
}

}  // namespace meshprep::detail
