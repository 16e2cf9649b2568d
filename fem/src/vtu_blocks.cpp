#include "vtu_blocks.h"

#include "byte_order.h"

#include <zlib.h>

#include <vector>

namespace meshprep::detail {
namespace {

// zlib cannot expand data more than about 1032 times (deflate's longest match per bit sequence):
// a block announcing more is a lie, refused before memory is reserved for it.
constexpr std::uint64_t max_zlib_ratio = 1032;

std::uint64_t header_value(ByteStream& in, const BlockFormat& f) {
  const std::string bytes = in.take(f.header_64 ? 8 : 4);
  return f.header_64 ? load_value<std::uint64_t>(bytes.data(), f.little_endian)
                     : load_value<std::uint32_t>(bytes.data(), f.little_endian);
}

std::string inflate_block(const std::string& compressed, std::uint64_t size, std::uint64_t block) {
  if (size > compressed.size() * max_zlib_ratio + 64)
    throw BadData{"compressed block " + std::to_string(block) + " announces " + std::to_string(size) +
                  " bytes from " + std::to_string(compressed.size()) + ", more than zlib can expand"};
  std::string out(size, '\0');
  uLongf out_size = static_cast<uLongf>(size);
  const int status = uncompress(reinterpret_cast<Bytef*>(out.data()), &out_size,
                                reinterpret_cast<const Bytef*>(compressed.data()), static_cast<uLong>(compressed.size()));
  if (status != Z_OK || out_size != size)
    throw BadData{"compressed block " + std::to_string(block) + " does not inflate to the " + std::to_string(size) +
                  " bytes its header announces (zlib: " + (status == Z_OK ? "fewer bytes" : zError(status)) + ")"};
  return out;
}

}  // namespace

std::string read_block(ByteStream& in, const BlockFormat& f) {
  if (!f.zlib) return in.take(header_value(in, f));
  const std::uint64_t num_blocks = header_value(in, f);
  const std::uint64_t block_size = header_value(in, f);
  const std::uint64_t last_size = header_value(in, f);
  const std::size_t header_bytes = f.header_64 ? 8 : 4;
  if (num_blocks > in.max_left() / header_bytes)
    throw BadData{"the compression header announces " + std::to_string(num_blocks) + " blocks, more than the data holds"};
  std::vector<std::uint64_t> compressed_sizes(num_blocks);
  for (std::uint64_t& size : compressed_sizes) size = header_value(in, f);
  std::string data;
  for (std::uint64_t b = 0; b < num_blocks; ++b) {
    const std::uint64_t size = b + 1 == num_blocks && last_size != 0 ? last_size : block_size;
    data += inflate_block(in.take(compressed_sizes[b]), size, b);
  }
  return data;
}

}  // namespace meshprep::detail
