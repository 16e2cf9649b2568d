#include "meshprep/pipeline/pipeline_config.h"

#include "config_text.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/core/size_parameters.h"
#include "meshprep/fem/fem_parameters.h"
#include "meshprep/preprocess/enhance/enhance_parameters.h"
#include "meshprep/preprocess/patches/patches_parameters.h"
#include "meshprep/preprocess/reconstruct/reconstruct_parameters.h"
#include "meshprep/preprocess/reconstruct/variation_rule.h"
#include "meshprep/preprocess/repair/repair_parameters.h"
#include "meshprep/preprocess/simplify/simplify_parameters.h"
#include "meshprep/preprocess/smooth/smooth_parameters.h"
#include "meshprep/quality/quality_parameters.h"

#include <cmath>
#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

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

Key number(const char* section, const ParameterInfo& info, double& field) {
  const Range range = info.range;
  const std::string type = "number in " + range.text();
  return {section, info.key, type, info.help,
          [&field, range, type](const Json& v) {
            if (!v.is_number() || !range.contains(v.get<double>())) throw BadValue{"expected a " + type + ", not " + shown(v)};
            field = v.get<double>();
          },
          [&field] { return OrderedJson(field); }};
}

// A number >= 0, or "inf" (JSON has no infinity), written back the same way.
Key number_or_inf(const char* section, const ParameterInfo& info, double& field) {
  const std::string type = "number in [0, inf) or \"inf\"";
  return {section, info.key, type, info.help,
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

// A number in the range, or "auto" (unset: the stage decides), written back the same way.
Key number_or_auto(const char* section, const ParameterInfo& info, std::optional<double>& field) {
  const Range range = info.range;
  const std::string type = "number in " + range.text() + " or \"auto\"";
  return {section, info.key, type, info.help,
          [&field, range, type](const Json& v) {
            if (v.is_string() && v.get<std::string>() == "auto") {
              field.reset();
              return;
            }
            if (!v.is_number() || !range.contains(v.get<double>())) throw BadValue{"expected a " + type + ", not " + shown(v)};
            field = v.get<double>();
          },
          [&field] { return field ? OrderedJson(*field) : OrderedJson("auto"); }};
}

// A length (core/size_field.h): a positive number, "2%" (of the diagonal), or "auto" (unset).
// A length from the file: a positive number or "N%"; nullopt for anything else.
std::optional<Length> length_from(const Json& v) {
  if (v.is_number() && v.get<double>() > 0 && std::isfinite(v.get<double>())) return Length{v.get<double>(), false};
  if (!v.is_string()) return std::nullopt;
  try {
    return parse_length(v.get<std::string>(), "");
  } catch (const InvalidInput&) {
    return std::nullopt;
  }
}

OrderedJson length_json(const Length& length) {
  return length.relative ? OrderedJson(length_text(length)) : OrderedJson(length.value);
}

Key length_or_auto(const char* section, const ParameterInfo& info, std::optional<Length>& field) {
  const std::string type = "positive number, \"N%\" (of the diagonal) or \"auto\"";
  return {section, info.key, type, info.help,
          [&field, type](const Json& v) {
            if (v.is_string() && v.get<std::string>() == "auto") {
              field.reset();
              return;
            }
            const std::optional<Length> length = length_from(v);
            if (!length) throw BadValue{"expected a " + type + ", not " + shown(v)};
            field = length;
          },
          [&field] { return field ? length_json(*field) : OrderedJson("auto"); }};
}

Key count(const char* section, const ParameterInfo& info, std::size_t& field) {
  const Range range = info.range;
  const std::string type = "integer in " + range.text();
  return {section, info.key, type, info.help,
          [&field, range, type](const Json& v) {
            if (!v.is_number_integer() || v.get<long long>() < 0 || !range.contains(static_cast<double>(v.get<std::size_t>())))
              throw BadValue{"expected an " + type + ", not " + shown(v)};
            field = v.get<std::size_t>();
          },
          [&field] { return OrderedJson(field); }};
}

Key flag(const char* section, const std::string& name, bool& field, std::string description) {
  return {section, name, "true or false", std::move(description),
          [&field](const Json& v) {
            if (!v.is_boolean()) throw BadValue{"expected true or false, not " + shown(v)};
            field = v.get<bool>();
          },
          [&field] { return OrderedJson(field); }};
}

Key flag(const char* section, const ParameterInfo& info, bool& field) { return flag(section, info.key, field, info.help); }

// A string naming one of `choices`, stored as the matching value of type T.
template <class T>
Key choice(const char* section, const std::string& name, T& field, Choices<T> choices, std::string description) {
  const std::string type = "one of " + choice_names(choices);
  return {section, name, type, std::move(description),
          [&field, choices, type](const Json& v) {
            if (v.is_string())
              for (const auto& [text, value] : choices)
                if (v.get<std::string>() == text) {
                  field = value;
                  return;
                }
            // 4.1 unquoted is a number: say that the value must be the text.
            throw BadValue{"expected " + type + (v.is_string() ? "" : " as a string (in quotes)") + ", not " + shown(v)};
          },
          [&field, choices] {
            const std::string chosen = choice_name(choices, field);
            return chosen.empty() ? OrderedJson(nullptr) : OrderedJson(chosen);
          }};
}

std::vector<Key> repair_keys(PipelineConfig::Repair& r) {
  return {flag("repair", "enabled", r.enabled,
               "weld split vertices, split faces at T-junctions, drop degenerate and duplicate faces, split "
               "non-manifold edges and vertices, drop lone faces (fins), orient, fill holes and remove "
               "self-intersections in the input before it is checked (meshprep repair)"),
          number("repair", repair_parameters().weld_tolerance, r.params.weld_tolerance),
          number_or_auto("repair", repair_parameters().max_hole, r.params.max_hole),
          flag("repair", repair_parameters().keep_cavities, r.params.keep_cavities),
          choice("repair", repair_parameters().route.key, r.params.route, repair_routes(),
                 repair_parameters().route.help),
          count("repair", repair_parameters().envelope_cells, r.params.envelope_cells),
          number("repair", repair_parameters().time_limit_seconds, r.params.time_limit_seconds)};
}

std::vector<Key> reconstruct_keys(PipelineConfig::Reconstruct& r) {
  ReconstructParams& p = r.params;
  const ReconstructParameters& info = reconstruct_parameters();
  const Range grid = info.resolution.range;
  const std::string grid_type = "[NX, NY], integers in " + grid.text();
  std::vector<Key> keys;
  keys.push_back({"reconstruct", info.resolution.key, grid_type, info.resolution.help + " (unless spacing or vertices is set)",
                  [&p, grid, grid_type](const Json& v) {
                    const auto in_range = [&grid](const Json& n) {
                      return n.is_number_integer() && n.get<long long>() >= 0 &&
                             grid.contains(static_cast<double>(n.get<long long>()));
                    };
                    if (!(v.is_array() && v.size() == 2 && in_range(v[0]) && in_range(v[1])))
                      throw BadValue{"expected " + grid_type + ", not " + shown(v)};
                    p.columns = v[0].get<std::size_t>();
                    p.rows = v[1].get<std::size_t>();
                  },
                  [&p] { return OrderedJson::array({p.columns, p.rows}); }});
  keys.push_back(number("reconstruct", info.spacing, p.spacing));
  keys.push_back(count("reconstruct", info.vertices, p.vertices));
  keys.push_back(count("reconstruct", info.leaf_size, p.fit.leaf_size));
  keys.push_back(count("reconstruct", info.neighbors, p.fit.neighbors));
  keys.push_back({"reconstruct", info.variation_threshold.key, "a number >= 0 or \"pNN\" (a percentile)",
                  info.variation_threshold.help,
                  [&p](const Json& v) {
                    if (!v.is_string() && !v.is_number()) throw BadValue{variation_rule_error(shown(v))};
                    const std::string text = v.is_string() ? v.get<std::string>() : shown(v);
                    if (!apply_variation_rule(text, p.fit)) throw BadValue{variation_rule_error(text)};
                  },
                  [&p] { return OrderedJson(variation_rule_text(p.fit)); }});
  keys.push_back(number("reconstruct", info.variation_growth, p.fit.variation_growth));
  keys.push_back(number("reconstruct", info.max_gap, p.max_gap));
  keys.push_back(flag("reconstruct", info.fill_holes, p.fill_holes));
  keys.push_back(flag("reconstruct", info.adaptive, r.adaptive));
  return keys;
}

std::vector<Key> patches_keys(PipelineConfig::Patches& p) {
  const PatchParameters& info = patch_parameters();
  std::vector<Key> keys;
  keys.push_back(number_or_auto("patches", info.feature_angle_deg, p.params.feature_angle_deg));
  keys.push_back(flag("patches", info.resegment, p.params.resegment));
  keys.push_back({"patches", info.renames.key, "an object {\"OLD\": \"NEW\", ...}", info.renames.help,
                  [&p](const Json& v) {
                    if (!v.is_object()) throw BadValue{"expected an object {\"OLD\": \"NEW\"}, not " + shown(v)};
                    p.params.renames.clear();
                    for (const auto& [from, to] : v.items()) {
                      if (!to.is_string()) throw BadValue{"the new name of '" + from + "' is not a string: " + shown(to)};
                      p.params.renames.emplace_back(from, to.get<std::string>());
                    }
                  },
                  [&p] {
                    OrderedJson renames = OrderedJson::object();
                    for (const auto& [from, to] : p.params.renames) renames[from] = to;
                    return renames;
                  }});
  keys.push_back({"patches", info.merges.key, "an array of arrays of names [[\"A\", \"B\"], ...]", info.merges.help,
                  [&p](const Json& v) {
                    const auto names = [](const Json& list) {
                      if (!list.is_array()) return false;
                      for (const Json& name : list)
                        if (!name.is_string()) return false;
                      return true;
                    };
                    if (!v.is_array()) throw BadValue{"expected an array of arrays of names, not " + shown(v)};
                    p.params.merges.clear();
                    for (const Json& list : v) {
                      if (!names(list)) throw BadValue{"expected an array of names, not " + shown(list)};
                      p.params.merges.push_back(list.get<std::vector<std::string>>());
                    }
                  },
                  [&p] { return OrderedJson(p.params.merges); }});
  return keys;
}

std::vector<Key> simplify_keys(PipelineConfig::Simplify& s) {
  const SimplifyParameters& info = simplify_parameters();
  const Range ratio_range = info.keep_ratio.range;
  const std::string ratio_type = "null or a number in " + ratio_range.text();
  std::vector<Key> keys;
  keys.push_back(flag("simplify", "enabled", s.enabled, "run the bending-energy edge collapse"));
  keys.push_back({"simplify", info.keep_ratio.key, ratio_type,
                  info.keep_ratio.help + "; null = " + parameter_text(PipelineConfig::Simplify::kTerrainRatio) +
                      " for a reconstructed terrain, no simplification for a mesh",
                  [&s, ratio_range, ratio_type](const Json& v) {
                    if (v.is_null()) {
                      s.ratio.reset();
                      return;
                    }
                    if (!v.is_number() || !ratio_range.contains(v.get<double>()))
                      throw BadValue{"expected " + ratio_type + ", not " + shown(v)};
                    s.ratio = v.get<double>();
                  },
                  [&s] { return s.ratio ? OrderedJson(*s.ratio) : OrderedJson(nullptr); }});
  keys.push_back(count("simplify", info.target_faces, s.params.target_faces));
  keys.push_back(choice("simplify", info.cost.key, s.params.cost, collapse_costs(), info.cost.help));
  keys.push_back(number("simplify", info.min_angle_deg, s.params.min_angle_deg));
  keys.push_back(number("simplify", info.max_error, s.params.max_error));
  keys.push_back(flag("simplify", info.polish, s.params.polish));
  return keys;
}

std::vector<Key> smooth_keys(PipelineConfig::Smooth& s) {
  SmoothParams& p = s.params;
  const SmoothParameters& info = smooth_parameters();
  std::vector<Key> keys;
  keys.push_back(flag("smooth", "enabled", s.enabled, "denoise (off by default: a clean surface only moves away)"));
  keys.push_back(choice("smooth", info.method.key, p.method, smooth_methods(), info.method.help));
  keys.push_back(count("smooth", info.iterations, p.iterations));
  keys.push_back(count("smooth", info.neighbors, p.neighbors));
  keys.push_back(number_or_inf("smooth", info.smoothing, p.smoothing));
  keys.push_back(number("smooth", info.relaxation, p.relaxation));
  keys.push_back(number("smooth", info.feature_angle_deg, p.feature_angle_deg));
  keys.push_back(flag("smooth", info.adaptive, p.adaptive));
  keys.push_back(flag("smooth", info.preserve_volume, p.preserve_volume));
  return keys;
}

std::vector<Key> enhance_keys(PipelineConfig::Enhance& e) {
  EnhanceParams& p = e.params;
  const EnhanceParameters& info = enhance_parameters();
  std::vector<Key> keys;
  keys.push_back(flag("enhance", "enabled", e.enabled, "the statistical triangle enhancement against the input"));
  keys.push_back(count("enhance", info.iterations, p.iterations));
  keys.push_back(number_or_auto("enhance", info.max_deviation, p.max_deviation));
  keys.push_back(number("enhance", info.target_min_angle_deg, p.target_min_angle_deg));
  keys.push_back(number("enhance", info.feature_angle_deg, p.feature_angle_deg));
  keys.push_back(flag("enhance", info.flips, p.flips));
  keys.push_back(choice("enhance", info.remesh.key, p.remesh, enhance_remesh_modes(), info.remesh.help));
  keys.push_back(count("enhance", info.max_faces, p.max_faces));
  keys.push_back(number("enhance", info.time_limit_seconds, p.time_limit_seconds));
  return keys;
}

std::vector<Key> size_keys(SizeParams& s) {
  const SizeParameters& info = size_parameters();
  return {length_or_auto("size", info.size, s.size),
          length_or_auto("size", info.size_min, s.size_min),
          length_or_auto("size", info.size_max, s.size_max),
          number_or_auto("size", info.grading, s.grading),
          number_or_auto("size", info.curvature_points, s.curvature_points),
          number_or_auto("size", info.thickness_layers, s.thickness_layers),
          {"size", info.patch_sizes.key, "an object {\"NAME\": length, ...}", info.patch_sizes.help,
           [&s](const Json& v) {
             if (!v.is_object()) throw BadValue{"expected an object {\"NAME\": length}, not " + shown(v)};
             s.patch_sizes.clear();
             for (const auto& [name, size] : v.items()) {
               const std::optional<Length> length = length_from(size);
               if (!length) throw BadValue{"the size of '" + name + "' is no positive number or \"N%\": " + shown(size)};
               s.patch_sizes[name] = *length;
             }
           },
           [&s] {
             OrderedJson sizes = OrderedJson::object();
             for (const auto& [name, size] : s.patch_sizes) sizes[name] = length_json(size);
             return sizes;
           }},
          {"size", info.regions.key,
           "an array of {\"box\": [x0, y0, z0, x1, y1, z1], \"size\": length} and {\"sphere\": [x, y, z, r], \"size\": "
           "length}",
           info.regions.help,
           [&s](const Json& v) {
             const std::string expected = "expected an array of {\"box\": [x0, y0, z0, x1, y1, z1], \"size\": length} or "
                                          "{\"sphere\": [x, y, z, r], \"size\": length}, not ";
             if (!v.is_array()) throw BadValue{expected + shown(v)};
             s.regions.clear();
             for (const Json& item : v) {
               const auto numbers = [&item](const char* shape, std::size_t count) {
                 const Json& list = item.at(shape);
                 bool ok = list.is_array() && list.size() == count;
                 for (std::size_t i = 0; ok && i < count; ++i) ok = list[i].is_number();
                 return ok;
               };
               if (!item.is_object() || item.size() != 2 || !item.contains("size") ||
                   !((item.contains("box") && numbers("box", 6)) || (item.contains("sphere") && numbers("sphere", 4))))
                 throw BadValue{expected + shown(item)};
               const std::optional<Length> length = length_from(item.at("size"));
               if (!length) throw BadValue{"a region's size is no positive number or \"N%\": " + shown(item.at("size"))};
               SizeRegion region;
               region.size = *length;
               if (item.contains("box")) {
                 const std::vector<double> c = item.at("box").get<std::vector<double>>();
                 region.lo = Vec3(c[0], c[1], c[2]);
                 region.hi = Vec3(c[3], c[4], c[5]);
               } else {
                 const std::vector<double> c = item.at("sphere").get<std::vector<double>>();
                 region.shape = SizeRegion::Shape::sphere;
                 region.center = Vec3(c[0], c[1], c[2]);
                 region.radius = c[3];
               }
               s.regions.push_back(region);
             }
           },
           [&s] {
             OrderedJson regions = OrderedJson::array();
             for (const SizeRegion& r : s.regions) {
               OrderedJson item;
               if (r.shape == SizeRegion::Shape::box) item["box"] = {r.lo.x(), r.lo.y(), r.lo.z(), r.hi.x(), r.hi.y(), r.hi.z()};
               else item["sphere"] = {r.center.x(), r.center.y(), r.center.z(), r.radius};
               item["size"] = length_json(r.size);
               regions.push_back(item);
             }
             return regions;
           }}};
}

std::vector<Key> quality_keys(PipelineConfig::Quality& q) {
  return {count("quality", quality_parameters().distance_samples, q.params.distance_samples)};
}

std::vector<Key> tetrahedralize_keys(PipelineConfig::Tetrahedralize& t) {
  TetParams& p = t.params;
  const TetParameters& info = tet_parameters();
  std::vector<Key> keys;
  keys.push_back(flag("tetrahedralize", "enabled", t.enabled, "TetGen tetrahedralisation of the final surface"));
  keys.push_back(number("tetrahedralize", info.radius_edge, p.radius_edge));
  keys.push_back(number("tetrahedralize", info.min_dihedral_deg, p.min_dihedral_deg));
  keys.push_back(number("tetrahedralize", info.max_volume_relative, p.max_volume_relative));
  keys.push_back({"tetrahedralize", info.keep_surface.key, "true, false or \"auto\"",
                  info.keep_surface.help + "; auto: yes for a closed surface, no for an extruded block",
                  [&t](const Json& v) {
                    if (v.is_boolean()) t.keep_surface = v.get<bool>();
                    else if (v.is_string() && v.get<std::string>() == "auto") t.keep_surface.reset();
                    else throw BadValue{"expected true, false or \"auto\", not " + shown(v)};
                  },
                  [&t] { return t.keep_surface ? OrderedJson(*t.keep_surface) : OrderedJson("auto"); }});
  keys.push_back(number("tetrahedralize",
                        {"extrude_base", "", "an open height field becomes a block with its base this far below the "
                         "lowest point; 0 = use extrude_base_relative", {0, INFINITY, false, true}},
                        t.extrude_base));
  keys.push_back(number("tetrahedralize",
                        {"extrude_base_relative", "", "the same depth / bounding-box diagonal", {0, 100, true, false}},
                        t.extrude_base_relative));
  keys.push_back(count("tetrahedralize", element_order_parameters().order, t.element_order.order));
  keys.push_back(choice<std::string>("tetrahedralize", "format", t.format,
                                     {{"msh", "msh"}, {"vtu", "vtu"}, {"mesh", "mesh"}, {"inp", "inp"}, {"node", "node"}, {"xdmf", "xdmf"}},
                                     "the tet mesh file tets.FORMAT: Gmsh, VTK XML, Medit, Abaqus/CalculiX, TetGen, XDMF + HDF5 (dolfinx)"));
  keys.push_back(choice<MshVersion>("tetrahedralize", "msh_version", t.export_options.msh_version,
                                    {{"4.1", MshVersion::V41}, {"2.2", MshVersion::V22}}, "Gmsh format version (msh)"));
  keys.push_back(flag("tetrahedralize", "binary", t.export_options.binary,
                      "binary msh (vtu and xdmf are binary anyway; mesh, inp and node cannot be)"));
  keys.push_back(flag("tetrahedralize", "ascii", t.export_options.ascii,
                      "ASCII vtu instead of zlib-compressed binary data (the other formats but xdmf are ASCII anyway)"));
  return keys;
}

std::vector<Key> improve_keys(PipelineConfig::Improve& i) {
  ImproveParams& p = i.params;
  const ImproveParameters& info = improve_parameters();
  std::vector<Key> keys;
  keys.push_back(flag("improve", "enabled", i.enabled,
                      "improve TetGen's tets (flips, smoothing, new inner vertices; boundary vertices slide on the surface within "
                      "improve.boundary_deviation)"));
  // The preset before the goals: a file read back sets the preset's goals, then the goals as written.
  keys.push_back({"improve", info.tet_quality.key, "one of default, high, custom", info.tet_quality.help,
                  [&p](const Json& v) {
                    if (!v.is_string()) throw BadValue{"expected one of default, high, custom, not " + shown(v)};
                    try {
                      apply_tet_quality(p, v.get<std::string>());
                    } catch (const InvalidInput&) {
                      throw BadValue{"expected one of default, high, custom, not " + shown(v)};
                    }
                  },
                  [&p] { return OrderedJson(tet_quality_of(p)); }});
  keys.push_back(number("improve", info.goal_min_dihedral_deg, p.goal_min_dihedral_deg));
  keys.push_back(number("improve", info.goal_max_dihedral_deg, p.goal_max_dihedral_deg));
  keys.push_back(flag("improve", info.insertion, p.insertion));
  keys.push_back(count("improve", info.max_passes, p.max_passes));
  keys.push_back(number_or_auto("improve", info.boundary_deviation, p.boundary_deviation));
  keys.push_back(number("improve", info.time_limit_seconds, p.time_limit_seconds));
  return keys;
}

std::vector<Key> knife_edges_keys(PipelineConfig::KnifeEdges& k) {
  return {flag("knife_edges", "enabled", k.enabled,
               "open the surface's knife edges and caps that hold the tets below improve.goal_min_dihedral_deg, "
               "at most the default goal's (flips and collapses, each within enhance.max_deviation of the input, listed in the report)")};
}

std::vector<Key> verdict_keys(TetThresholds& t) {
  const VerdictParameters& info = verdict_parameters();
  return {number("verdict", info.min_dihedral_deg, t.min_dihedral_deg),
          number("verdict", info.max_dihedral_deg, t.max_dihedral_deg),
          count("verdict", info.max_inverted_tets, t.max_inverted_tets)};
}

std::vector<std::pair<std::string, std::vector<Key>>> sections(PipelineConfig& c) {
  return {{"repair", repair_keys(c.repair)},           {"reconstruct", reconstruct_keys(c.reconstruct)},
          {"patches", patches_keys(c.patches)},             {"simplify", simplify_keys(c.simplify)},
          {"smooth", smooth_keys(c.smooth)},                {"size", size_keys(c.size)},
          {"enhance", enhance_keys(c.enhance)},
          {"knife_edges", knife_edges_keys(c.knife_edges)}, {"quality", quality_keys(c.quality)},             {"tetrahedralize", tetrahedralize_keys(c.tetrahedralize)},
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
      if (std::none_of(keys.begin(), keys.end(), [&](const Key& k) { return k.name == key_name; })) {
        std::string valid;
        for (const Key& k : keys) valid += (valid.empty() ? "" : ", ") + k.name;
        throw InvalidInput(origin + ": unknown key '" + section_name + "." + key_name + "'; valid keys of " +
                           section_name + ": " + valid);
      }
    }
    // In the table's order, not the file's: a preset (improve.tet_quality) comes before the keys
    // it sets, whichever order the file lists them in.
    for (Key& key : keys) {
      if (!value.contains(key.name)) continue;
      try {
        key.read(value.at(key.name));
      } catch (const BadValue& e) {
        throw InvalidInput(origin + ": " + section_name + "." + key.name + ": " + e.what);
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
  check_size_params(config.size);
  check_enhance_params(config.enhance.params);
  check_tet_params(config.tetrahedralize.params);
  check_improve_params(config.improve.params);
  check_thresholds(config.verdict);
  const PipelineConfig::Tetrahedralize& t = config.tetrahedralize;
  if (!(t.extrude_base >= 0 && std::isfinite(t.extrude_base)))
    throw InvalidInput("tetrahedralize: extrude_base must be finite and >= 0, not " + std::to_string(t.extrude_base));
  if (!(t.extrude_base_relative > 0 && std::isfinite(t.extrude_base_relative)))
    throw InvalidInput("tetrahedralize: extrude_base_relative must be finite and > 0, not " +
                       std::to_string(t.extrude_base_relative));
  try {
    check_tet_export_options("tets." + t.format, t.export_options);
  } catch (const InvalidInput& e) {  // named by the key (or keys) that asked it
    const char* keys = !t.export_options.ascii ? "binary" : !t.export_options.binary ? "ascii" : "binary, ascii";
    throw InvalidInput(std::string("tetrahedralize: ") + keys + ": " + e.what());
  }
}

void detail::apply_config_text(std::string_view text, const std::string& origin, PipelineConfig& config) {
  // JSON lets an object give a key twice and the parser keeps the last value without a word: a
  // key given twice is refused, named by its path (issue 45, item 12).
  std::vector<std::set<std::string>> keys_of_object;  // the objects being parsed, innermost last
  std::vector<std::string> path;                         // the key of each enclosing value
  const Json::parser_callback_t refuse_repeated_keys = [&](int, Json::parse_event_t event, Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start:
        keys_of_object.emplace_back();
        break;
      case Json::parse_event_t::object_end:
        keys_of_object.pop_back();
        if (!path.empty() && keys_of_object.size() < path.size()) path.pop_back();
        break;
      case Json::parse_event_t::key: {
        const std::string key = parsed.get<std::string>();
        path.resize(keys_of_object.size() - 1);
        path.push_back(key);
        if (!keys_of_object.back().insert(key).second) {
          std::string name;
          for (const std::string& k : path) name += (name.empty() ? "" : ".") + k;
          throw InvalidInput(origin + ": " + name + " is given twice (JSON would keep the last value without a word); "
                             "give it once");
        }
        break;
      }
      default:
        break;
    }
    return true;
  };
  Json json;
  try {
    json = Json::parse(text, refuse_repeated_keys);
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
