#pragma once
/// \file text_scanner.h
/// Tokenizer shared by the text readers: whitespace-separated tokens, line numbers, optional
/// end-of-line comments. Works on an in-memory buffer; never allocates.

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
  /// Number (1-based) of the line the scanner is on.
  std::size_t line() const { return line_; }

 private:
  bool is_comment(char c) const { return comment_ != '\0' && c == comment_; }
  void skip_blanks();

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
