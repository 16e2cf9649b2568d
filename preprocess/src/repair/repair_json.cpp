#include "meshprep/preprocess/repair/repair.h"

#include <nlohmann/json.hpp>

namespace meshprep {

nlohmann::ordered_json to_json(const RepairResult& result) {
  nlohmann::ordered_json json;
  json["weld_distance"] = result.weld_distance;
  json["input_closed"] = result.input_closed;
  json["welded_vertices"] = result.welded_vertices;
  json["degenerate_faces"] = result.degenerate_faces;
  json["duplicate_faces"] = result.duplicate_faces;
  json["unused_vertices"] = result.unused_vertices;
  json["t_junction_splits"] = result.t_junction_splits;
  json["split_edges"] = result.split_edges;
  json["split_vertices"] = result.split_vertices;
  json["dropped_lone_faces"] = result.dropped_lone_faces;
  json["components"] = result.components;
  json["flipped_faces"] = result.flipped_faces;
  json["inverted_components"] = result.inverted_components;
  json["filled_holes"] = result.filled_holes;
  json["open_holes"] = result.open_holes;
  json["holes"] = nlohmann::ordered_json::array();
  for (const RepairHole& h : result.holes) {
    nlohmann::ordered_json hole;
    hole["rim_vertices"] = h.rim_vertices;
    hole["rim_length"] = h.rim_length;
    hole["filled"] = h.filled;
    if (!h.filled) hole["left_open"] = h.left_open;
    if (h.filled) {
      hole["patch_faces"] = h.patch_faces;
      hole["patch_vertices"] = h.patch_vertices;
      hole["patch_area"] = h.patch_area;
      hole["plane_distance"] = h.plane_distance;
      hole["faired"] = h.faired;
    }
    json["holes"].push_back(hole);
  }
  json["intersecting_pairs"] = result.intersecting_pairs;
  json["cut_faces"] = result.cut_faces;
  json["removed_faces"] = result.removed_faces;
  json["nested_components"] = result.nested_components;
  json["cavities"] = result.cavities;
  json["separated_pinches"] = result.separated_pinches;
  json["time_seconds"] = result.seconds;
  return json;
}

}  // namespace meshprep
