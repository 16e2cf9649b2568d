#pragma once
// Numbers written as text into a buffer that goes to the stream in large pieces. Each `out << x`
// on a std::ostream builds a sentry and goes through the locale's num_put, which on the femur's
// tets cost more than the formatting itself (bench/bench_writers.sh); std::to_chars into a
// buffer does not.

#include <array>
#include <charconv>
#include <cstddef>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>

namespace meshprep::detail {

/// Appends an integer in decimal, or a floating-point value in the shortest form that reads back
/// to the same value of its type (std::to_chars).
template <class T, class = std::enable_if_t<std::is_arithmetic_v<T>>>
void append_number(std::string& text, T value) {
  std::array<char, 32> digits;  // the longest shortest-round-trip double is 24 characters
  const auto result = std::to_chars(digits.data(), digits.data() + digits.size(), value);
  text.append(digits.data(), static_cast<std::size_t>(result.ptr - digits.data()));
}

class TextBuffer {
 public:
  explicit TextBuffer(std::ostream& out) : out_(out) { text_.reserve(kFlushSize + 64); }
  TextBuffer(const TextBuffer&) = delete;
  TextBuffer& operator=(const TextBuffer&) = delete;
  /// What is still buffered is lost unless flush() was called: a destructor must not write to a
  /// stream that may throw.
  ~TextBuffer() = default;

  TextBuffer& operator<<(char c) {
    text_ += c;
    return flush_if_full();
  }
  TextBuffer& operator<<(std::string_view s) {
    text_ += s;
    return flush_if_full();
  }
  TextBuffer& operator<<(const char* s) { return *this << std::string_view(s); }
  TextBuffer& operator<<(const std::string& s) { return *this << std::string_view(s); }

  /// A number as append_number writes it.
  template <class T, class = std::enable_if_t<std::is_arithmetic_v<T>>>
  TextBuffer& operator<<(T value) {
    append_number(text_, value);
    return flush_if_full();
  }

  void flush() {
    out_.write(text_.data(), static_cast<std::streamsize>(text_.size()));
    text_.clear();
  }

 private:
  static constexpr std::size_t kFlushSize = 1 << 20;

  TextBuffer& flush_if_full() {
    if (text_.size() >= kFlushSize) flush();
    return *this;
  }

  std::ostream& out_;
  std::string text_;
};

}  // namespace meshprep::detail
