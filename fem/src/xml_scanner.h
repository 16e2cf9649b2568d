#pragma once
// A minimal XML tag scanner for the VTU reader (import_vtu.cpp): tags and their attributes,
// nothing else; text, comments, declarations and DOCTYPEs are skipped.

#include "readers.h"
#include "text_scanner.h"

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace meshprep::detail {

struct XmlTag {
  std::string_view name;
  bool closing = false;       // </name>
  bool self_closing = false;  // <name ... />
  std::vector<std::pair<std::string_view, std::string_view>> attributes;
  std::size_t begin = 0;  // offset of '<'
  std::size_t end = 0;    // offset after '>'

  std::optional<std::string_view> attribute(std::string_view key) const {
    for (const auto& [k, v] : attributes)
      if (k == key) return v;
    return std::nullopt;
  }
};

inline bool is_xml_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == ':' ||
         c == '-' || c == '.';
}

inline bool is_xml_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

class XmlScanner {
 public:
  XmlScanner(const std::string& name, std::string_view data) : name_(name), data_(data) {}

  // The next tag at or after `from`, skipping text, comments, declarations and DOCTYPEs; false at the end.
  bool next(std::size_t from, XmlTag& tag) const {
    for (std::size_t at = from;;) {
      at = data_.find('<', at);
      if (at == std::string_view::npos) return false;
      const std::string_view rest = data_.substr(at);
      if (rest.substr(0, 4) == "<!--") {
        at = skip_to(at, "-->");
      } else if (rest.substr(0, 2) == "<?") {
        at = skip_to(at, "?>");
      } else if (rest.substr(0, 2) == "<!") {
        at = skip_to(at, ">");
      } else {
        parse_tag(at, tag);
        return true;
      }
    }
  }

  // "<name>: line N: <problem>" for the byte at `offset`.
  [[noreturn]] void fail_at(std::size_t offset, const std::string& problem) const {
    const auto line = static_cast<std::size_t>(std::count(data_.begin(), data_.begin() + std::min(offset, data_.size()), '\n'));
    fail(name_, at_line(line + 1) + problem);
  }

 private:
  std::size_t skip_to(std::size_t at, std::string_view end) const {
    const std::size_t found = data_.find(end, at);
    if (found == std::string_view::npos) fail_at(at, "unterminated XML markup (no " + std::string(end) + ")");
    return found + end.size();
  }

  std::string_view name_at(std::size_t& i) const {
    const std::size_t start = i;
    while (i < data_.size() && is_xml_name_char(data_[i])) ++i;
    if (i == start) fail_at(start, "malformed XML tag");
    return data_.substr(start, i - start);
  }

  void skip_spaces(std::size_t& i) const {
    while (i < data_.size() && is_xml_space(data_[i])) ++i;
  }

  void parse_tag(std::size_t at, XmlTag& tag) const {
    tag = XmlTag{};
    tag.begin = at;
    std::size_t i = at + 1;
    if (i < data_.size() && data_[i] == '/') {
      tag.closing = true;
      ++i;
    }
    tag.name = name_at(i);
    for (;;) {
      skip_spaces(i);
      if (i >= data_.size()) fail_at(at, "unterminated XML tag <" + std::string(tag.name) + ">");
      if (data_[i] == '>') break;
      if (data_[i] == '/' && i + 1 < data_.size() && data_[i + 1] == '>') {
        tag.self_closing = true;
        ++i;
        break;
      }
      const std::string_view key = name_at(i);
      skip_spaces(i);
      if (i >= data_.size() || data_[i] != '=') fail_at(i, "attribute " + quoted(key) + " has no value");
      ++i;
      skip_spaces(i);
      if (i >= data_.size() || (data_[i] != '"' && data_[i] != '\'')) fail_at(i, "attribute " + quoted(key) + " is not quoted");
      const std::size_t close = data_.find(data_[i], i + 1);
      if (close == std::string_view::npos) fail_at(i, "attribute " + quoted(key) + " is not closed");
      tag.attributes.emplace_back(key, data_.substr(i + 1, close - i - 1));
      i = close + 1;
    }
    tag.end = i + 1;
  }

  const std::string& name_;
  std::string_view data_;
};

}  // namespace meshprep::detail
