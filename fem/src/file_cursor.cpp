#include "file_cursor.h"

#include "readers.h"

namespace meshprep::detail {

FileCursor::FileCursor(const std::string& name, std::string_view data, char comment)
    : name_(name), data_(data), in_(data, comment) {}

void FileCursor::set_binary(bool little_endian) {
  binary_ = true;
  little_endian_ = little_endian;
}

std::string FileCursor::where() const {
  return binary_ ? "byte " + std::to_string(in_.offset()) + ": " : at_line(in_.line());
}

void FileCursor::fail_here(const std::string& problem) const { fail(name_, where() + problem); }

void FileCursor::fail_truncated() const { fail(name_, "truncated: the file ends inside " + context_); }

std::string_view FileCursor::token() {
  if (!in_.seek_token()) fail_truncated();
  return in_.token();
}

std::string_view FileCursor::peek_token() const {
  TextScanner ahead = in_;
  return ahead.seek_token() ? ahead.token() : std::string_view();
}

std::string_view FileCursor::field(const char* what) {
  if (in_.at_line_end()) fail_here(std::string(what) + " missing (the line ends early)");
  return in_.token();
}

std::uint64_t FileCursor::count(const char* what) {
  const std::string_view t = token();
  const std::int64_t value = integer_of(t, what);
  if (value < 0) fail_here(std::string(what) + " " + quoted(t) + " is negative");
  return static_cast<std::uint64_t>(value);
}

// A Gmsh section's end marker ($EndNodes) where a number should be: the counts disagree, which is
// what to say, not that "$EndNodes" is no number.
void FileCursor::fail_if_section_ends(std::string_view token, const char* what) const {
  if (!token.empty() && token[0] == '$')
    fail_here(std::string(what) + " expected, but the section ends (" + quoted(token) +
              "): it holds fewer entries than its header announces");
}

std::int64_t FileCursor::integer_of(std::string_view token, const char* what) const {
  std::int64_t value = 0;
  if (parse_int(token, value)) return value;
  fail_if_section_ends(token, what);
  fail_here(std::string(what) + ": " + quoted(token) + " is not an integer");
}

double FileCursor::real_of(std::string_view token, const char* what) const {
  double value = 0;
  if (parse_double(token, value)) return value;
  fail_if_section_ends(token, what);
  fail_here(std::string(what) + ": " + quoted(token) + " is not a number");
}

void FileCursor::start_binary_data() {
  if (!in_.at_line_end()) fail_here("unexpected " + quoted(in_.token()) + " before binary data");
  if (!in_.next_line()) fail_truncated();
}

std::string_view FileCursor::bytes(std::size_t n) {
  std::string_view taken;
  if (!in_.take_bytes(n, taken)) fail_truncated();
  return taken;
}

bool FileCursor::skip_past(std::string_view marker) {
  const std::size_t at = data_.find(marker, in_.offset());
  if (at == std::string_view::npos) return false;
  bytes(at - in_.offset() + marker.size());
  return true;
}

bool FileCursor::next_line_starts_with(std::string_view prefix) const {
  const std::size_t newline = data_.find('\n', in_.offset());
  return newline != std::string_view::npos && data_.substr(newline + 1, prefix.size()) == prefix;
}

void FileCursor::next_line() {
  if (!in_.next_line()) fail_truncated();
}

void FileCursor::skip_to_blank_line() {
  do next_line();
  while (!in_.at_line_end());
}

}  // namespace meshprep::detail
