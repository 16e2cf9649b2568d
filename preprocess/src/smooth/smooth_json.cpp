#include "meshprep/preprocess/smooth/smooth.h"
#include "meshprep/preprocess/smooth/smooth_parameters.h"

#include "meshprep/quality/json_values.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace meshprep {

nlohmann::ordered_json to_json(const SmoothResult& result, const SmoothParams& params) {
  using Json = nlohmann::ordered_json;
  Json json;
  json["method"] = choice_name(smooth_methods(), params.method);
  json["iterations"] = result.iterations;
  if (params.method == SmoothMethod::Rbf) {
    json["neighbors"] = params.neighbors;
    json["smoothing"] = std::isinf(params.smoothing) ? Json("inf") : Json(params.smoothing);
    json["relaxation"] = params.relaxation;
    json["feature_angle_deg"] = params.feature_angle_deg;
    json["adaptive"] = params.adaptive;
    json["noise_level"] = result.noise_level;
    json["noise_crease_vertices"] = result.noise_crease_vertices;
    json["vertices_kept"] = {{"corners", result.corner_vertices},
                             {"boundary", result.boundary_vertices},
                             {"unfitted", result.unfitted_vertices},
                             {"undone_for_self_intersections", result.undone_vertices},
                             {"not_moved", result.not_moved_vertices}};
    json["feature_line_vertices"] = result.feature_line_vertices;
  }
  json["preserve_volume"] = params.preserve_volume;
  json["volume_before"] = result.volume_before ? json_number(*result.volume_before) : nullptr;
  json["volume_after"] = result.volume_after ? json_number(*result.volume_after) : nullptr;
  json["volume_change_relative"] =
      result.volume_before ? json_number(*result.volume_after / *result.volume_before - 1) : nullptr;
  json["max_displacement"] = result.max_displacement;
  json[kGuardsTakenBackKey] = json_taken_back(result.taken_back);
  json["time_seconds"] = result.seconds;
  return json;
}

}  // namespace meshprep
