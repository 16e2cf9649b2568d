#include "meshprep/preprocess/enhance/enhance.h"
#include "meshprep/preprocess/enhance/enhance_parameters.h"
#include "meshprep/quality/json_values.h"

#include <nlohmann/json.hpp>

namespace meshprep {

nlohmann::ordered_json to_json(const QualityTail& tail) {
  nlohmann::ordered_json json;
  json["mean_q"] = tail.mean_q;
  json["stddev_q"] = tail.stddev_q;
  json["q_p05"] = tail.q_p05;
  json["under_target_fraction"] = tail.under_target_fraction;
  json["min_angle_deg"] = tail.min_angle_deg;
  return json;
}

nlohmann::ordered_json to_json(const EnhanceResult& result, const EnhanceParams& params) {
  nlohmann::ordered_json json;
  json["rounds"] = result.rounds;
  json["kept_round"] = result.kept_round;
  json["flips"] = result.flips;
  json["cap_flips"] = result.cap_flips;
  json["removed_vertices"] = result.removed_vertices;
  json["split_edges"] = result.split_edges;
  json["line_vertices"] = result.line_vertices;
  json["fixed_vertices"] = result.fixed_vertices;
  json["undone_moves"] = result.undone_moves;
  json[kGuardsTakenBackKey] = json_taken_back(result.taken_back);
  json["remesh"] = {{"remeshed", result.remeshed},
                    {"splits", result.remesh_splits},
                    {"collapses", result.remesh_collapses},
                    {"flips", result.remesh_flips},
                    {"crossing_refinements", result.remesh_crossing_refinements},
                    {"sizing_shortest", result.sizing_shortest},
                    {"sizing_base", result.sizing_base},
                    {"sizing_faces", result.sizing_faces},
                    {"sizing_capped", result.sizing_capped},
                    {"seconds", result.remesh_seconds}};
  json["parameters"] = {{"max_deviation", result.max_deviation},
                        {"max_deviation_auto", !params.max_deviation},
                        {"target_min_angle_deg", params.target_min_angle_deg},
                        {"feature_angle_deg", params.feature_angle_deg},
                        {"tail_k", params.tail_k},
                        {"tail_weight", params.tail_weight},
                        {"fidelity_weight", params.fidelity_weight},
                        {"flip_dihedral_deg", params.flip_dihedral_deg},
                        {"flips", params.flips},
                        {"remesh", choice_name(enhance_remesh_modes(), params.remesh)},
                        {"max_faces", params.max_faces},
                        {"time_limit_seconds", params.time_limit_seconds}};
  // The user's size settings (core/size_field.h), lengths as written: "2%" or a number; unset null.
  const auto length = [](const std::optional<Length>& l) {
    if (!l) return nlohmann::ordered_json(nullptr);
    return l->relative ? nlohmann::ordered_json(length_text(*l)) : nlohmann::ordered_json(l->value);
  };
  const auto number = [](const std::optional<double>& v) { return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr); };
  const SizeParams& size = params.size;
  json["parameters"]["size"] = {{"size", length(size.size)},
                                {"size_min", length(size.size_min)},
                                {"size_max", length(size.size_max)},
                                {"grading", size.grading_used()},
                                {"curvature_points", number(size.curvature_points)},
                                {"thickness_layers", number(size.thickness_layers)}};
  json["tail_before"] = to_json(result.before);
  json["tail_after"] = to_json(result.after);
  json["time_seconds"] = result.seconds;
  json["stopped"] = result.stopped_by_time_limit ? nlohmann::ordered_json("time limit") : nlohmann::ordered_json(nullptr);
  return json;
}

}  // namespace meshprep
