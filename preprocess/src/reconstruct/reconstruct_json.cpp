#include "meshprep/preprocess/reconstruct/reconstruct.h"
#include "meshprep/preprocess/reconstruct/variation_rule.h"

#include "meshprep/quality/json_values.h"

#include <nlohmann/json.hpp>

namespace meshprep {

nlohmann::ordered_json to_json(const ReconstructResult& result, const ReconstructParams& params) {
  nlohmann::ordered_json json;
  json["vertices"] = result.mesh.points.size();
  json["faces"] = result.mesh.triangles.size();
  json["grid"] = {{"columns", result.columns}, {"rows", result.rows}};
  json["patches"] = result.patches;
  json["leaf_size"] = params.fit.leaf_size;
  json["neighbors"] = params.fit.neighbors;
  json["variation"] = {{"rule", variation_rule_text(params.fit)},
                       {"threshold", result.variation_threshold},
                       {"growth", params.fit.variation_growth},
                       {"grown_patches", result.grown_patches},
                       {"patch_sigma", json_distribution(summarize(result.patch_variation))},
                       {"vertex_sigma", json_distribution(summarize(result.vertex_variation))}};
  json["max_gap"] = result.max_gap;
  json["gap_faces_left_out"] = result.gap_triangles;
  json["fill_holes"] = params.fill_holes;
  json["filled_faces"] = result.filled_triangles;
  json["reference_normal"] = {result.normal.x(), result.normal.y(), result.normal.z()};
  json[kGuardsTakenBackKey] = json_taken_back(result.taken_back);
  json["time_seconds"] = result.seconds;
  return json;
}

}  // namespace meshprep
