#include "meshprep/preprocess/repair/repair.h"

#include <nlohmann/json.hpp>

namespace meshprep {

nlohmann::ordered_json to_json(const RepairResult& result) {
  nlohmann::ordered_json json;
  json["weld_distance"] = result.weld_distance;
  json["welded_vertices"] = result.welded_vertices;
  json["degenerate_faces"] = result.degenerate_faces;
  json["duplicate_faces"] = result.duplicate_faces;
  json["unused_vertices"] = result.unused_vertices;
  json["split_edges"] = result.split_edges;
  json["split_vertices"] = result.split_vertices;
  json["components"] = result.components;
  json["flipped_faces"] = result.flipped_faces;
  json["inverted_components"] = result.inverted_components;
  json["time_seconds"] = result.seconds;
  return json;
}

}  // namespace meshprep
