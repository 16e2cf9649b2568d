#pragma once
// The reading position in a tet mesh file, shared by the readers: text tokens with line numbers
// (core's TextScanner), raw values for formats that embed binary data between text lines (Gmsh
// binary .msh, legacy VTK BINARY), and messages that say where: "<name>: line N: <problem>" in
// text, "<name>: byte N: <problem>" once the file is known to be binary.

#include "byte_order.h"
#include "text_scanner.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace meshprep::detail {

class FileCursor {
 public:
  /// `name` and `data` must outlive the cursor; `comment` starts a comment to the end of the line.
  FileCursor(const std::string& name, std::string_view data, char comment = '\0');

  /// From now on raw values are in this byte order and messages give byte offsets.
  void set_binary(bool little_endian);
  bool binary() const { return binary_; }
  /// What is being read, for the message of a file that ends too early ("the $Nodes section").
  void set_context(std::string context) { context_ = std::move(context); }

  /// "line N: " or "byte N: ".
  std::string where() const;
  [[noreturn]] void fail_here(const std::string& problem) const;
  /// "<name>: truncated: the file ends inside <context>".
  [[noreturn]] void fail_truncated() const;

  /// Whether no token is left.
  bool at_end() { return !in_.seek_token(); }
  /// The next token, on this line or a later one.
  std::string_view token();
  /// The next token, on this line or a later one, without moving past it (empty at the end).
  std::string_view peek_token() const;
  /// The next token on the current line (`what` names it when the line has ended).
  std::string_view field(const char* what);
  /// Whether the current line has no token left.
  bool at_line_end() { return in_.at_line_end(); }
  void skip_line() { in_.skip_line(); }
  /// The rest of the current line, blanks trimmed (a name that may hold spaces).
  std::string_view rest_of_line() { return in_.rest_of_line(); }

  /// The next token as an integer, a count (>= 0) or a real number; `what` names it in messages.
  std::int64_t integer(const char* what) { return integer_of(token(), what); }
  std::uint64_t count(const char* what);
  double real(const char* what) { return real_of(token(), what); }
  std::int64_t integer_of(std::string_view token, const char* what) const;
  double real_of(std::string_view token, const char* what) const;

  /// Binary data starts at the next line's first byte: the current line must have no token left.
  void start_binary_data();
  /// The next `n` raw bytes (truncated if fewer are left).
  std::string_view bytes(std::size_t n);
  /// The next raw value of type T in the byte order of set_binary.
  template <class T>
  T load() {
    return load_value<T>(bytes(sizeof(T)).data(), little_endian_);
  }
  /// Bytes after the position (to cap reservations by what the file can still hold).
  std::size_t bytes_left() const { return in_.bytes_left(); }
  /// Bytes from the start of the file to the position.
  std::size_t offset() const { return in_.offset(); }
  /// Moves past the next occurrence of `marker` (a raw search: binary data may hold anything);
  /// false, not moving, if there is none.
  bool skip_past(std::string_view marker);
  /// Whether the line after the current one starts with `prefix` (the position does not move).
  bool next_line_starts_with(std::string_view prefix) const;
  /// Moves to the start of the next line. \throws InvalidInput (truncated) if there is none.
  void next_line();
  /// Moves to the next line that holds no token (the end of a block of lines).
  void skip_to_blank_line();

 private:
  void fail_if_section_ends(std::string_view token, const char* what) const;

  const std::string& name_;
  std::string_view data_;
  TextScanner in_;
  std::string context_ = "the file";
  bool binary_ = false;
  bool little_endian_ = true;
};

}  // namespace meshprep::detail
