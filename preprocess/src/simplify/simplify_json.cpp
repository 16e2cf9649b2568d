#include "meshprep/preprocess/simplify/simplify.h"
#include "meshprep/quality/json_values.h"

#include <nlohmann/json.hpp>

namespace meshprep {

nlohmann::ordered_json to_json(const SimplifyResult& result) {
  nlohmann::ordered_json json;
  json["faces_before"] = result.faces_before;
  json["faces_after"] = result.faces_after;
  json["target_faces"] = result.target_faces;
  json["reached_target"] = result.reached_target;
  json["time_seconds"] = result.seconds;
  json["collapses"] = result.collapses;
  json["rejected"] = {{"topology", result.rejected_topology},
                      {"shape", result.rejected_shape},
                      {"max_error", result.rejected_error}};
  json["energy_evaluations"] = result.energy_evaluations;
  json["intersection_retries"] = result.intersection_retries;
  json[kGuardsTakenBackKey] = json_taken_back(result.taken_back);
  json["reshapes"] = result.reshapes;
  json["stuck_restarts"] = result.stuck_restarts;
  json["queue_order"] = result.banded_queue ? "cost_bands" : "cost";
  json["polish"] = {{"flips", result.polish_flips}, {"moves", result.polish_moves}, {"fit_moves", result.fit_moves}};
  return json;
}

}  // namespace meshprep
