#pragma once
// The bytes of a VTU data array's binary data (import_vtu.cpp): raw or base64-decoded on the way,
// read as VTK's blocks (a header of byte counts, then the data, zlib-compressed or not).

#include "xml_scanner.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace meshprep::detail {

// A problem with one data array's content; the reader names the array.
struct BadData {
  std::string problem;
};

inline int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

class ByteStream {
 public:
  ByteStream(std::string_view data, bool base64) : data_(data), base64_(base64) {}

  // At most this many bytes are left (exact for raw data).
  std::size_t max_left() const { return pending_.size() + (base64_ ? (data_.size() - pos_) / 4 * 3 : data_.size() - pos_); }

  // The next n bytes.
  std::string take(std::size_t n) {
    if (n > max_left()) throw BadData{"the data ends before the " + std::to_string(n) + " bytes it announces"};
    std::string out;
    out.reserve(n);
    if (!base64_) {
      out.assign(data_.substr(pos_, n));
      pos_ += n;
      return out;
    }
    while (out.size() < n) {
      if (pending_.empty()) decode_group();
      const std::size_t moved = std::min(n - out.size(), pending_.size());
      out.append(pending_, 0, moved);
      pending_.erase(0, moved);
    }
    return out;
  }

 private:
  // Four characters (blanks between them skipped) into 1-3 bytes in pending_.
  void decode_group() {
    int values[4];
    int padding = 0;
    for (int k = 0; k < 4; ++k) {
      while (pos_ < data_.size() && is_xml_space(data_[pos_])) ++pos_;
      if (pos_ == data_.size()) throw BadData{"the base64 data ends before the bytes it announces"};
      const char c = data_[pos_++];
      if (c == '=' && k >= 2) {
        ++padding;
        values[k] = 0;
        continue;
      }
      values[k] = base64_value(c);
      if (values[k] < 0 || padding > 0) throw BadData{"invalid base64 character " + quoted(std::string_view(&c, 1))};
    }
    const unsigned bits = (static_cast<unsigned>(values[0]) << 18) | (static_cast<unsigned>(values[1]) << 12) |
                          (static_cast<unsigned>(values[2]) << 6) | static_cast<unsigned>(values[3]);
    const char bytes[3] = {static_cast<char>(bits >> 16), static_cast<char>((bits >> 8) & 0xff),
                           static_cast<char>(bits & 0xff)};
    pending_.append(bytes, static_cast<std::size_t>(3 - padding));
  }

  std::string_view data_;
  bool base64_;
  std::size_t pos_ = 0;
  std::string pending_;  // decoded, not yet taken
};

struct BlockFormat {
  bool little_endian = true;
  bool header_64 = false;  // header_type="UInt64"
  bool zlib = false;
};

// One binary block: header, then the data (inflated when compressed). \throws BadData
std::string read_block(ByteStream& in, const BlockFormat& format);

}  // namespace meshprep::detail
