#pragma once
/// \file text_scanner.h
/// Tokenizer shared by the text readers: whitespace-separated tokens, line numbers, optional
/// end-of-line comments, and raw byte blocks for formats that embed binary data between text
/// lines (Gmsh binary .msh, legacy VTK BINARY). Works on an in-memory buffer; never allocates.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace meshprep::detail {

/// Splits a text buffer into whitespace-separated tokens and tracks the line number.
/// With a comment character, everything from it to the end of the line is skipped.
class TextScanner {
 public:
  /// `text` must outlive the scanner; `first_line` is the number of its first line.
  explicit TextScanner(std::string_view text, char comment = '\0', std::size_t first_line = 1);

  /// Skips blanks, line ends and comments up to the next token; false if none is left.
  bool seek_token();
  /// The next token of the current line, or an empty view at the end of the line.
  std::string_view token();
  /// Whether the current line has no token left.
  bool at_line_end();
  /// Discards the rest of the current line.
  void skip_line();
  /// The rest of the current line without its leading and trailing blanks (a name that may hold
  /// spaces); the scanner moves to the line's end. A comment character is not special here.
  std::string_view rest_of_line();
  /// Discards the rest of the current line and its line end: the scanner is at the first byte of
  /// the next line (where a binary block starts). False if the text ends on this line.
  bool next_line();
  /// The next `n` bytes as they are, without skipping anything before them (binary data); false,
  /// consuming nothing, if fewer are left. Line ends among them are not counted in line().
  bool take_bytes(std::size_t n, std::string_view& bytes);
  /// Bytes from the start of the text to the scanner's position (for messages about binary data).
  std::size_t offset() const { return static_cast<std::size_t>(pos_ - begin_); }
  /// Bytes left after the scanner's position.
  std::size_t bytes_left() const { return static_cast<std::size_t>(end_ - pos_); }
  /// Number (1-based) of the line the scanner is on.
  std::size_t line() const { return line_; }

 private:
  bool is_comment(char c) const { return comment_ != '\0' && c == comment_; }
  void skip_blanks();

  const char* begin_;
  const char* pos_;
  const char* end_;
  char comment_;
  std::size_t line_;
};

/// Parses a whole token as a double (a leading '+', "nan" and "inf" accepted; values beyond
/// the double range become +-inf). False if the token is not entirely a number.
bool parse_double(std::string_view token, double& value);

/// Parses a whole token as a decimal integer (a leading '+' accepted). False if the token is
/// not entirely an integer or does not fit.
bool parse_int(std::string_view token, std::int64_t& value);

/// The token quoted for an error message, shortened if long.
std::string quoted(std::string_view token);

}  // namespace meshprep::detail
