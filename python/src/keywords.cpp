#include "keywords.h"

#include "meshprep/core/errors.h"

#include <algorithm>

namespace meshprep::python {
namespace {

bool contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

// The keys of `section` in the key table.
std::vector<std::string> section_keys(const std::string& section) {
  std::vector<std::string> keys;
  for (const ConfigKeyDoc& doc : describe_config())
    if (doc.key.compare(0, section.size() + 1, section + ".") == 0) keys.push_back(doc.key.substr(section.size() + 1));
  return keys;
}

}  // namespace

nlohmann::json json_value(const py::handle& value, const std::string& what) {
  if (value.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::int_>(value)) return value.cast<long long>();
  if (py::isinstance<py::float_>(value)) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::dict>(value)) {
    nlohmann::json object = nlohmann::json::object();
    for (const auto& [key, item] : py::reinterpret_borrow<py::dict>(value)) {
      if (!py::isinstance<py::str>(key)) throw InvalidInput(what + ": dict keys must be str");
      const std::string name = key.cast<std::string>();
      object[name] = json_value(item, what + "." + name);
    }
    return object;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    nlohmann::json array = nlohmann::json::array();
    for (const py::handle item : value) array.push_back(json_value(item, what));
    return array;
  }
  if (py::hasattr(value, "item") && py::hasattr(value, "dtype") && py::len(value.attr("shape")) == 0)
    return json_value(value.attr("item")(), what);  // a numpy scalar
  throw InvalidInput(what + ": expected a number, a str, a bool, a list or a dict, not " +
                     std::string(py::str(value.get_type().attr("__name__"))));
}

void apply_keywords(const Keywords& spec, const py::dict& kwargs, PipelineConfig& config) {
  const std::string origin = "meshprep." + spec.function + "()";
  const std::vector<std::string> own_keys = spec.own.empty() ? std::vector<std::string>{} : section_keys(spec.own);
  nlohmann::json sections = nlohmann::json::object();
  for (const auto& [key, value] : kwargs) {
    const std::string name = key.cast<std::string>();
    if (contains(spec.sections, name)) {
      nlohmann::json section = json_value(value, name);
      if (section.is_boolean()) section = {{"enabled", section}};
      // A section with a key of its own name takes a plain value as that key's: size="2%".
      else if (!section.is_object() && contains(section_keys(name), name)) section = {{name, section}};
      if (!section.is_object())
        throw InvalidInput(origin + ": " + name + " takes a dict of its keys (" + joined(section_keys(name)) + ")" +
                           (contains(section_keys(name), "enabled") ? " or True/False" : "") +
                           (contains(section_keys(name), name) ? " or the value of " + name + "." + name : ""));
      sections[name].update(section);
    } else if (contains(own_keys, name) && !contains(spec.refused, name)) {
      sections[spec.own][name] = json_value(value, name);
    } else {
      std::vector<std::string> valid;
      for (const std::string& k : own_keys)
        if (!contains(spec.refused, k)) valid.push_back(k);
      for (const std::string& s : spec.sections) valid.push_back(s + "={...}");
      valid.push_back("threads");  // the call's own (stages.cpp), as every command's --threads
      valid.push_back("time_limit");  // and --time-limit
      throw InvalidInput(origin + ": unknown keyword '" + name + "'; it takes " + joined(valid));
    }
  }
  apply_config(sections, origin, config);
}

std::string keyword_doc(const Keywords& spec, const PipelineConfig& config) {
  const nlohmann::ordered_json defaults = to_json(config);
  std::string doc;
  for (const ConfigKeyDoc& key : describe_config()) {
    const std::size_t dot = key.key.find('.');
    const std::string section = key.key.substr(0, dot), name = key.key.substr(dot + 1);
    const bool own = section == spec.own && !contains(spec.refused, name);
    if (!own && !contains(spec.sections, section)) continue;
    const std::string keyword = own ? name : section + "={\"" + name + "\": ...}";
    doc += "    " + keyword + " (" + key.type + ", default " + defaults[section][name].dump() + "): " + key.description + "\n";
  }
  return doc;
}

}  // namespace meshprep::python
