#include "meshprep/pipeline/pipeline_config.h"

#include "config_text.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/preprocess/reconstruct/variation_rule.h"

#include <cmath>
#include <functional>
#include <sstream>
#include <utility>

namespace meshprep {
namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

// A value the key cannot take; the caller adds the file and the key.
struct BadValue {
  std::string what;
};

// One key of the file, bound to its field of a PipelineConfig.
struct Key {
  std::string section, name, type, description;
  std::function<void(const Json&)> read;  ///< throws BadValue
  std::function<OrderedJson()> write;
};

// Whether `value` holds arrays or objects more than `levels` deep (recursing `levels` times at most).
bool nested_deeper_than(const Json& value, int levels) {
  if (!value.is_structured()) return false;
  if (levels == 0) return true;
  for (const Json& item : value)
    if (nested_deeper_than(item, levels - 1)) return true;
  return false;
}

// A value as a message quotes it. dump() recurses once per level of nesting, so a deeply nested
// value (a file of 10^5 brackets) is named by its kind instead of overflowing the stack.
std::string shown(const Json& value) {
  constexpr int max_levels = 16;
  if (nested_deeper_than(value, max_levels)) {
    return std::string(value.is_array() ? "an array" : "an object") + " nested over " + std::to_string(max_levels) +
           " levels deep";
  }
  return value.dump();
}

std::string range_text(double lo, double hi, bool lo_open) {
  std::ostringstream out;
  out << (lo_open ? "(" : "[") << lo << ", ";
  if (std::isinf(hi)) out << "inf)";
  else out << hi << "]";
  return out.str();
}

Key number(const char* section, const char* name, double& field, double lo, double hi, bool lo_open,
           std::string description) {
  const std::string type = "number in " + range_text(lo, hi, lo_open);
  return {section, name, type, std::move(description),
          [&field, lo, hi, lo_open, type](const Json& v) {
            if (!v.is_number()) throw BadValue{"expected a " + type + ", not " + shown(v)};
            const double x = v.get<double>();
            if (!(lo_open ? x > lo : x >= lo) || !(x <= hi)) throw BadValue{"expected a " + type + ", not " + shown(v)};
            field = x;
          },
          [&field] { return OrderedJson(field); }};
}

// A number >= 0, or "inf" (JSON has no infinity), written back the same way.
Key number_or_inf(const char* section, const char* name, double& field, std::string description) {
  const std::string type = "number in [0, inf) or \"inf\"";
  return {section, name, type, std::move(description),
          [&field, type](const Json& v) {
            if (v.is_string() && v.get<std::string>() == "inf") {
              field = INFINITY;
              return;
            }
            if (!v.is_number() || !(v.get<double>() >= 0)) throw BadValue{"expected a " + type + ", not " + shown(v)};
            field = v.get<double>();
          },
          [&field] { return std::isinf(field) ? OrderedJson("inf") : OrderedJson(field); }};
}

Key count(const char* section, const char* name, std::size_t& field, std::size_t lo, std::size_t hi,
          std::string description) {
  const std::string type = "integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return {section, name, type, std::move(description),
          [&field, lo, hi, type](const Json& v) {
            if (!v.is_number_integer() || v.get<long long>() < 0) throw BadValue{"expected an " + type + ", not " + shown(v)};
            const auto x = v.get<std::size_t>();
            if (x < lo || x > hi) throw BadValue{"expected an " + type + ", not " + shown(v)};
            field = x;
          },
          [&field] { return OrderedJson(field); }};
}

Key flag(const char* section, const char* name, bool& field, std::string description) {
  return {section, name, "true or false", std::move(description),
          [&field](const Json& v) {
            if (!v.is_boolean()) throw BadValue{"expected true or false, not " + shown(v)};
            field = v.get<bool>();
          },
          [&field] { return OrderedJson(field); }};
}

// A string naming one of `choices`, stored as the matching value of type T.
template <class T>
Key choice(const char* section, const char* name, T& field, std::vector<std::pair<std::string, T>> choices,
           std::string description) {
  std::string type = "one of";
  for (std::size_t i = 0; i < choices.size(); ++i) type += (i ? ", " : " ") + choices[i].first;
  return {section, name, type, std::move(description),
          [&field, choices, type](const Json& v) {
            if (v.is_string())
              for (const auto& [text, value] : choices)
                if (v.get<std::string>() == text) {
                  field = value;
                  return;
                }
            throw BadValue{"expected " + type + ", not " + shown(v)};
          },
          [&field, choices] {
            for (const auto& [text, value] : choices)
              if (field == value) return OrderedJson(text);
            return OrderedJson(nullptr);
          }};
}

std::vector<Key> reconstruct_keys(PipelineConfig::Reconstruct& r) {
  ReconstructParams& p = r.params;
  std::vector<Key> keys;
  keys.push_back({"reconstruct", "resolution", "[NX, NY], integers in [2, 100000]",
                  "grid vertices along the footprint (unless spacing or vertices is set)",
                  [&p](const Json& v) {
                    const bool ok = v.is_array() && v.size() == 2 && v[0].is_number_integer() && v[1].is_number_integer() &&
                                    v[0].get<long long>() >= 2 && v[1].get<long long>() >= 2 &&
                                    v[0].get<long long>() <= 100000 && v[1].get<long long>() <= 100000;
                    if (!ok) throw BadValue{"expected [NX, NY] with integers in [2, 100000], not " + shown(v)};
                    p.columns = v[0].get<std::size_t>();
                    p.rows = v[1].get<std::size_t>();
                  },
                  [&p] { return OrderedJson::array({p.columns, p.rows}); }});
  keys.push_back(number("reconstruct", "spacing", p.spacing, 0, INFINITY, false,
                        "grid spacing in the reference plane; 0 = use resolution"));
  keys.push_back(count("reconstruct", "vertices", p.vertices, 0, 100000000,
                       "about this many grid vertices on square cells; 0 = use resolution or spacing"));
  keys.push_back(count("reconstruct", "leaf_size", p.fit.leaf_size, 1, 100000,
                       "K: samples per k-d tree cell, one thin-plate patch each"));
  keys.push_back(count("reconstruct", "neighbors", p.fit.neighbors, 3, 1000, "samples interpolated by each patch"));
  keys.push_back({"reconstruct", "variation_threshold", "a number >= 0 or \"pNN\" (a percentile)",
                  "patches whose surface variation sigma exceeds this grow: the paper's 0.3, or a percentile of the "
                  "patches' sigma",
                  [&r](const Json& v) {
                    if (!v.is_string() && !v.is_number()) throw BadValue{variation_rule_error(shown(v))};
                    const std::string text = v.is_string() ? v.get<std::string>() : shown(v);
                    if (!apply_variation_rule(text, r.params.fit)) throw BadValue{variation_rule_error(text)};
                    r.variation_threshold = text;
                  },
                  [&r] { return OrderedJson(r.variation_threshold); }});
  keys.push_back(number("reconstruct", "variation_growth", p.fit.variation_growth, 1, 4, false,
                        "support radius factor of a grown patch (its samples grow by the square)"));
  keys.push_back(number("reconstruct", "max_gap", p.max_gap, 0, INFINITY, false,
                        "triangles farther than this from every sample are gaps; 0 = 3 x the median sample spacing"));
  keys.push_back(flag("reconstruct", "fill_holes", p.fill_holes,
                      "keep the triangles over interior gaps, flagged in the report, so the terrain can be closed "
                      "into a block; false leaves them out"));
  keys.push_back(flag("reconstruct", "adaptive", r.adaptive,
                      "vertices dense where the surface bends, sparse where flat (slower)"));
  return keys;
}

std::vector<Key> simplify_keys(PipelineConfig::Simplify& s) {
  std::vector<Key> keys;
  keys.push_back(flag("simplify", "enabled", s.enabled, "run the bending-energy edge collapse"));
  keys.push_back({"simplify", "ratio", "null or a number in (0, 1]",
                  "fraction of the faces kept; null = 0.07 for a reconstructed terrain, no simplification for a mesh",
                  [&s](const Json& v) {
                    if (v.is_null()) {
                      s.ratio.reset();
                      return;
                    }
                    if (!v.is_number() || !(v.get<double>() > 0 && v.get<double>() <= 1))
                      throw BadValue{"expected null or a number in (0, 1], not " + shown(v)};
                    s.ratio = v.get<double>();
                  },
                  [&s] { return s.ratio ? OrderedJson(*s.ratio) : OrderedJson(nullptr); }});
  keys.push_back(count("simplify", "target_faces", s.target_faces, 0, 1000000000,
                       "target number of faces; 0 = use ratio"));
  keys.push_back(choice<CollapseCost>("simplify", "cost", s.params.cost,
                                      {{"bending", CollapseCost::Bending},
                                       {"distance", CollapseCost::Distance},
                                       {"quadric", CollapseCost::Quadric}},
                                      "collapse cost (see meshprep simplify --help)"));
  keys.push_back(number("simplify", "min_angle_deg", s.params.min_angle_deg, 0, 59, false,
                        "collapses may not create a smaller triangle angle (degrees); 0 = off"));
  keys.push_back(number("simplify", "max_error", s.params.max_error, 0, 1, false,
                        "largest estimated deviation of a collapse / bounding-box diagonal; 0 = no limit"));
  keys.push_back(flag("simplify", "polish", s.params.polish, "flips and relaxation after collapsing"));
  return keys;
}

std::vector<Key> smooth_keys(PipelineConfig::Smooth& s) {
  SmoothParams& p = s.params;
  std::vector<Key> keys;
  keys.push_back(flag("smooth", "enabled", s.enabled, "denoise (off by default: a clean surface only moves away)"));
  keys.push_back(choice<SmoothMethod>("smooth", "method", p.method,
                                      {{"rbf", SmoothMethod::Rbf},
                                       {"taubin", SmoothMethod::Taubin},
                                       {"laplace", SmoothMethod::Laplace}},
                                      "rbf (the paper's) or the taubin and laplace baselines"));
  keys.push_back(count("smooth", "iterations", p.iterations, 1, 1000, "smoothing iterations"));
  keys.push_back(count("smooth", "neighbors", p.neighbors, 13, 200, "rbf: neighbours of each vertex's local surface"));
  keys.push_back(number_or_inf("smooth", "smoothing", p.smoothing,
                               "rbf: lambda of the weighted thin-plate smoothing spline; inf = the weighted "
                               "least-squares cubic; 0 interpolates"));
  keys.push_back(number("smooth", "relaxation", p.relaxation, 0, 1, false,
                        "rbf: how far each vertex goes towards its 1-ring's centroid before it is put on its surface"));
  keys.push_back(number("smooth", "feature_angle_deg", p.feature_angle_deg, 1, 180, false,
                        "rbf: edges with a larger dihedral angle are creases, kept sharp; 180 = none"));
  keys.push_back(flag("smooth", "preserve_volume", p.preserve_volume, "closed surfaces keep their volume"));
  return keys;
}

std::vector<Key> enhance_keys(PipelineConfig::Enhance& e) {
  EnhanceParams& p = e.params;
  std::vector<Key> keys;
  keys.push_back(flag("enhance", "enabled", e.enabled, "the statistical triangle enhancement against the input"));
  keys.push_back(count("enhance", "iterations", p.iterations, 1, 1000, "rounds at most"));
  keys.push_back({"enhance", "max_deviation", "number in (0, 1] or \"auto\"",
                  "a face may not move farther than this / bounding-box diagonal from the input surface; auto: as "
                  "far as the simplified surface already is, at most 0.002",
                  [&p](const Json& v) {
                    if (v.is_string() && v.get<std::string>() == "auto") {
                      p.max_deviation.reset();
                      return;
                    }
                    if (!v.is_number() || !(v.get<double>() > 0 && v.get<double>() <= 1))
                      throw BadValue{"expected a number in (0, 1] or \"auto\", not " + shown(v)};
                    p.max_deviation = v.get<double>();
                  },
                  [&p] { return p.max_deviation ? OrderedJson(*p.max_deviation) : OrderedJson("auto"); }});
  keys.push_back(number("enhance", "target_min_angle_deg", p.target_min_angle_deg, 1, 59, false,
                        "faces with a smaller angle (degrees) are always in the bad tail"));
  keys.push_back(number("enhance", "feature_angle_deg", p.feature_angle_deg, 1, 180, false,
                        "edges with a larger dihedral angle are creases: their vertices slide along them"));
  keys.push_back(flag("enhance", "flips", p.flips, "flip edges where moving vertices cannot help"));
  return keys;
}

std::vector<Key> quality_keys(PipelineConfig::Quality& q) {
  return {count("quality", "distance_samples", q.params.distance_samples, 1000, 100000000,
                "area-weighted samples per direction for the final Hausdorff and RMS distances")};
}

std::vector<Key> tetrahedralize_keys(PipelineConfig::Tetrahedralize& t) {
  TetParams& p = t.params;
  std::vector<Key> keys;
  keys.push_back(flag("tetrahedralize", "enabled", t.enabled, "TetGen tetrahedralisation of the final surface"));
  keys.push_back(number("tetrahedralize", "radius_edge", p.radius_edge, 0, 100, false,
                        "TetGen -q bound on circumradius / shortest edge; 0 = no refinement"));
  keys.push_back(number("tetrahedralize", "min_dihedral_deg", p.min_dihedral_deg, 0, 30, false,
                        "TetGen -q dihedral target (degrees); 0 = TetGen's default"));
  keys.push_back(number("tetrahedralize", "max_volume_relative", p.max_volume_relative, 0, 1, false,
                        "largest tet volume / enclosed volume; 0 = no bound"));
  keys.push_back({"tetrahedralize", "keep_surface", "true, false or \"auto\"",
                  "the boundary keeps exactly the surface triangles (TetGen -Y); auto: yes for a closed surface, "
                  "no for an extruded block",
                  [&t](const Json& v) {
                    if (v.is_boolean()) t.keep_surface = v.get<bool>();
                    else if (v.is_string() && v.get<std::string>() == "auto") t.keep_surface.reset();
                    else throw BadValue{"expected true, false or \"auto\", not " + shown(v)};
                  },
                  [&t] { return t.keep_surface ? OrderedJson(*t.keep_surface) : OrderedJson("auto"); }});
  keys.push_back(number("tetrahedralize", "extrude_base", t.extrude_base, 0, INFINITY, false,
                        "an open height field becomes a block with its base this far below the lowest point; 0 = use "
                        "extrude_base_relative"));
  keys.push_back(number("tetrahedralize", "extrude_base_relative", t.extrude_base_relative, 0, 100, true,
                        "the same depth / bounding-box diagonal"));
  keys.push_back(choice<std::string>("tetrahedralize", "format", t.format,
                                     {{"msh", "msh"}, {"vtu", "vtu"}, {"mesh", "mesh"}, {"inp", "inp"}, {"node", "node"}},
                                     "the tet mesh file tets.FORMAT: Gmsh, VTK XML, Medit, Abaqus/CalculiX, TetGen"));
  keys.push_back(choice<MshVersion>("tetrahedralize", "msh_version", t.export_options.msh_version,
                                    {{"4.1", MshVersion::V41}, {"2.2", MshVersion::V22}}, "Gmsh format version (msh)"));
  keys.push_back(flag("tetrahedralize", "binary", t.export_options.binary, "binary .msh"));
  return keys;
}

std::vector<Key> improve_keys(PipelineConfig::Improve& i) {
  ImproveParams& p = i.params;
  std::vector<Key> keys;
  keys.push_back(flag("improve", "enabled", i.enabled,
                      "improve TetGen's tets (flips, smoothing, new inner vertices; the boundary is kept exactly)"));
  keys.push_back(number("improve", "goal_min_dihedral_deg", p.goal_min_dihedral_deg, 0, 59, true,
                        "the tets with a smaller dihedral angle (degrees) are improved"));
  keys.push_back(number("improve", "goal_max_dihedral_deg", p.goal_max_dihedral_deg, 60, 179, true,
                        "... and those with a larger one (degrees)"));
  keys.push_back(flag("improve", "insertion", p.insertion, "insert inner vertices where flips and smoothing are stuck"));
  keys.push_back(count("improve", "max_passes", p.max_passes, 1, 1000, "passes over the tets below the goal, at most"));
  keys.push_back(number("improve", "time_limit_seconds", p.time_limit_seconds, 0, INFINITY, false,
                        "stop improving after this many seconds (the tets so far are kept); 0 = no limit"));
  return keys;
}

std::vector<Key> verdict_keys(TetThresholds& t) {
  std::vector<Key> keys;
  keys.push_back(number("verdict", "min_dihedral_deg", t.min_dihedral_deg, 0, 180, false,
                        "FEM-ready only if the tets' smallest dihedral angle is at least this (degrees); 0 = any"));
  keys.push_back(number("verdict", "max_dihedral_deg", t.max_dihedral_deg, 0, 180, false,
                        "FEM-ready only if the tets' largest dihedral angle is at most this (degrees); 180 = any"));
  keys.push_back(count("verdict", "max_inverted_tets", t.max_inverted_tets, 0, 1000000000,
                       "FEM-ready only if at most this many tets are inverted or flat (volume <= 0)"));
  return keys;
}

std::vector<std::pair<std::string, std::vector<Key>>> sections(PipelineConfig& c) {
  return {{"reconstruct", reconstruct_keys(c.reconstruct)}, {"simplify", simplify_keys(c.simplify)},
          {"smooth", smooth_keys(c.smooth)},                {"enhance", enhance_keys(c.enhance)},
          {"quality", quality_keys(c.quality)},             {"tetrahedralize", tetrahedralize_keys(c.tetrahedralize)},
          {"improve", improve_keys(c.improve)},             {"verdict", verdict_keys(c.verdict)}};
}

constexpr const char* kRunSection = "run";  // provenance written into pipeline.json, ignored on read

}  // namespace

void apply_config(const Json& json, const std::string& origin, PipelineConfig& config) {
  if (!json.is_object()) throw InvalidInput(origin + ": a configuration is a JSON object of sections, not " + shown(json));
  auto all = sections(config);
  // Named references, not structured bindings: C++17 lambdas cannot capture those (clang refuses).
  for (const auto& section_item : json.items()) {
    const std::string& section_name = section_item.key();
    const Json& value = section_item.value();
    if (section_name == kRunSection) continue;
    auto section = std::find_if(all.begin(), all.end(), [&](const auto& s) { return s.first == section_name; });
    if (section == all.end()) {
      std::string valid;
      for (const auto& s : all) valid += (valid.empty() ? "" : ", ") + s.first;
      throw InvalidInput(origin + ": unknown section '" + section_name + "'; valid sections: " + valid);
    }
    if (!value.is_object()) throw InvalidInput(origin + ": " + section_name + ": expected an object of keys, not " + shown(value));
    std::vector<Key>& keys = section->second;
    for (const auto& key_item : value.items()) {
      const std::string& key_name = key_item.key();
      const Json& key_value = key_item.value();
      auto key = std::find_if(keys.begin(), keys.end(), [&](const Key& k) { return k.name == key_name; });
      if (key == keys.end()) {
        std::string valid;
        for (const Key& k : keys) valid += (valid.empty() ? "" : ", ") + k.name;
        throw InvalidInput(origin + ": unknown key '" + section_name + "." + key_name + "'; valid keys of " +
                           section_name + ": " + valid);
      }
      try {
        key->read(key_value);
      } catch (const BadValue& e) {
        throw InvalidInput(origin + ": " + section_name + "." + key_name + ": " + e.what);
      }
    }
  }
  try {
    check_config(config);
  } catch (const InvalidInput& e) {
    throw InvalidInput(origin + ": " + e.what());
  }
}

void check_config(const PipelineConfig& config) {
  check_tet_params(config.tetrahedralize.params);
  check_improve_params(config.improve.params);
  check_thresholds(config.verdict);
  const PipelineConfig::Tetrahedralize& t = config.tetrahedralize;
  if (!(t.extrude_base >= 0 && std::isfinite(t.extrude_base)))
    throw InvalidInput("tetrahedralize: extrude_base must be finite and >= 0, not " + std::to_string(t.extrude_base));
  if (!(t.extrude_base_relative > 0 && std::isfinite(t.extrude_base_relative)))
    throw InvalidInput("tetrahedralize: extrude_base_relative must be finite and > 0, not " +
                       std::to_string(t.extrude_base_relative));
}

void detail::apply_config_text(std::string_view text, const std::string& origin, PipelineConfig& config) {
  Json json;
  try {
    json = Json::parse(text);
  } catch (const Json::exception& e) {
    // A parse_error or, for a number beyond the double range, an out_of_range; e.what() reads
    // "[json.exception.parse_error.101] parse error at line L, column C: ..."
    const std::string what = e.what();
    const std::size_t at = what.find("] ");
    throw InvalidInput(origin + ": not valid JSON: " + (at == std::string::npos ? what : what.substr(at + 2)));
  }
  apply_config(json, origin, config);
}

void read_config_file(const std::string& path, PipelineConfig& config) {
  detail::apply_config_text(read_input_file(path), path, config);
}

OrderedJson to_json(const PipelineConfig& config) {
  PipelineConfig copy = config;  // the keys bind to a mutable configuration
  OrderedJson json;
  for (const auto& [name, keys] : sections(copy)) {
    OrderedJson section = OrderedJson::object();
    for (const Key& key : keys) section[key.name] = key.write();
    json[name] = section;
  }
  return json;
}

std::vector<ConfigKeyDoc> describe_config() {
  PipelineConfig defaults;
  std::vector<ConfigKeyDoc> docs;
  for (const auto& [name, keys] : sections(defaults))
    for (const Key& key : keys) docs.push_back({name + "." + key.name, key.type, key.write(), key.description});
  return docs;
}

}  // namespace meshprep
