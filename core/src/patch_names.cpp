#include "meshprep/core/patch_names.h"

#include <algorithm>
#include <cctype>
#include <set>

namespace meshprep {
namespace {

bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_name_char(char c) { return is_letter(c) || (c >= '0' && c <= '9') || c == '_'; }

std::string upper(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return name;
}

}  // namespace

bool is_valid_name(std::string_view name) {
  return !name.empty() && name.size() <= kMaxNameLength && is_letter(name.front()) &&
         std::all_of(name.begin(), name.end(), is_name_char);
}

std::string sanitized_name(std::string_view name) {
  std::string clean;
  for (const char c : name) {
    if (is_name_char(c)) clean += c;
    else if (clean.empty() || clean.back() != '_') clean += '_';
  }
  if (clean.empty() || !is_letter(clean.front())) clean = "p_" + clean;
  if (clean.size() > kMaxNameLength) clean.resize(kMaxNameLength);
  return clean;
}

std::vector<RenamedTag> sanitize_names(TagNames& names) {
  std::vector<RenamedTag> renamed;
  std::set<std::string> taken;  // upper case
  for (auto& [tag, name] : names) {
    std::string clean = sanitized_name(name);
    const std::string base = clean;
    for (int k = 2; taken.count(upper(clean)); ++k) {
      const std::string suffix = "_" + std::to_string(k);
      clean = base.substr(0, std::min(base.size(), kMaxNameLength - suffix.size())) + suffix;
    }
    taken.insert(upper(clean));
    if (clean != name) {
      renamed.push_back({tag, name, clean});
      name = clean;
    }
  }
  return renamed;
}

std::string tag_name(const TagNames& names, int tag, std::string_view prefix) {
  const auto it = names.find(tag);
  return it != names.end() ? it->second : std::string(prefix) + "_" + std::to_string(tag);
}

}  // namespace meshprep
