#pragma once
// RFC 4648 base64 (private to the module): PNG data URIs and VTK XML binary arrays.

#include <cstdint>
#include <string>
#include <vector>

namespace meshprep::detail {

std::string base64(const std::uint8_t* bytes, std::size_t size);

inline std::string base64(const std::vector<std::uint8_t>& bytes) { return base64(bytes.data(), bytes.size()); }

}  // namespace meshprep::detail
