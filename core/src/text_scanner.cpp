#include "text_scanner.h"

#include <charconv>
#include <cstdlib>
#include <cstring>

namespace meshprep::detail {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// from_chars rejects a leading '+' that text formats allow.
std::string_view without_plus(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+') token.remove_prefix(1);
  return token;
}

}  // namespace

TextScanner::TextScanner(std::string_view text, char comment, std::size_t first_line)
    : begin_(text.data()), pos_(text.data()), end_(text.data() + text.size()), comment_(comment), line_(first_line) {}

void TextScanner::skip_blanks() {
  while (pos_ != end_ && is_blank(*pos_)) ++pos_;
  if (pos_ != end_ && is_comment(*pos_)) skip_line();
}

bool TextScanner::seek_token() {
  for (;;) {
    skip_blanks();
    if (pos_ == end_) return false;
    if (*pos_ != '\n') return true;
    ++pos_;
    ++line_;
  }
}

std::string_view TextScanner::token() {
  skip_blanks();
  const char* start = pos_;
  while (pos_ != end_ && *pos_ != '\n' && !is_blank(*pos_) && !is_comment(*pos_)) ++pos_;
  return {start, static_cast<std::size_t>(pos_ - start)};
}

bool TextScanner::at_line_end() {
  skip_blanks();
  return pos_ == end_ || *pos_ == '\n';
}

void TextScanner::skip_line() {
  const void* newline = std::memchr(pos_, '\n', static_cast<std::size_t>(end_ - pos_));
  pos_ = newline ? static_cast<const char*>(newline) : end_;
}

std::string_view TextScanner::rest_of_line() {
  while (pos_ != end_ && is_blank(*pos_)) ++pos_;
  const char* start = pos_;
  skip_line();
  const char* stop = pos_;
  while (stop != start && is_blank(stop[-1])) --stop;
  return {start, static_cast<std::size_t>(stop - start)};
}

bool TextScanner::next_line() {
  skip_line();
  if (pos_ == end_) return false;
  ++pos_;
  ++line_;
  return true;
}

bool TextScanner::take_bytes(std::size_t n, std::string_view& bytes) {
  if (bytes_left() < n) return false;
  bytes = {pos_, n};
  pos_ += n;
  return true;
}

bool parse_double(std::string_view token, double& value) {
  token = without_plus(token);
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ptr != end) return false;
  if (ec == std::errc::result_out_of_range) {
    // Overflow or underflow: strtod gives +-HUGE_VAL or the nearest denormal/zero, which the
    // readers then treat like any other value (infinities are rejected as non-finite).
    const std::string copy(token);
    value = std::strtod(copy.c_str(), nullptr);
    return true;
  }
  return ec == std::errc();
}

bool parse_int(std::string_view token, std::int64_t& value) {
  token = without_plus(token);
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end && !token.empty();
}

std::string quoted(std::string_view token) {
  constexpr std::size_t max_length = 40;
  std::string text = "'";
  for (const char c : token.substr(0, max_length)) text += (c >= ' ' && c <= '~') ? c : '?';
  return text + (token.size() > max_length ? "...'" : "'");
}

}  // namespace meshprep::detail
