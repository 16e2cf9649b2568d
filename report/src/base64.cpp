#include "base64.h"

namespace meshprep::detail {

std::string base64(const std::uint8_t* bytes, std::size_t size) {
  static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  for (std::size_t i = 0; i < size; i += 3) {
    const std::uint32_t chunk = std::uint32_t(bytes[i]) << 16 | (i + 1 < size ? std::uint32_t(bytes[i + 1]) << 8 : 0) |
                                (i + 2 < size ? std::uint32_t(bytes[i + 2]) : 0);
    out += alphabet[chunk >> 18 & 63];
    out += alphabet[chunk >> 12 & 63];
    out += i + 1 < size ? alphabet[chunk >> 6 & 63] : '=';
    out += i + 2 < size ? alphabet[chunk & 63] : '=';
  }
  return out;
}

}  // namespace meshprep::detail
