#include "meshprep/preprocess/repair/repair.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>

namespace meshprep {

std::string envelope_summary(const RepairResult& result) {
  if (!result.envelope) return {};
  const RepairEnvelope& e = *result.envelope;
  std::array<char, 160> figures;
  std::snprintf(figures.data(), figures.size(), "%.1e of the diagonal from the input at most, %.1e RMS", e.distance_max,
                e.distance_rms);
  std::array<char, 32> bound;
  std::snprintf(bound.data(), bound.size(), "%g", e.bound);
  std::string summary = "; " + e.reason + ": the solid rebuilt on a " + std::to_string(e.cells) +
                        "-cell grid (envelope route), " + figures.data();
  if (e.bound > 0)
    summary += ", " + std::to_string(e.places.size()) +
               (e.places.size() == RepairEnvelope::kListedPlaces ? " or more" : "") + " places over the " +
               bound.data() + " bound";
  if (e.reduced_faces > 0)
    summary += ", simplified from " + std::to_string(e.faces) + " to " + std::to_string(e.reduced_faces) + " faces";
  return summary;
}

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
  json["route"] = result.route;
  if (!result.envelope) {
    json["envelope"] = nullptr;
  } else {
    const RepairEnvelope& e = *result.envelope;
    nlohmann::ordered_json envelope;
    envelope["reason"] = e.reason;
    envelope["cells"] = e.cells;
    envelope["cell"] = e.cell;
    envelope["grid_points"] = e.grid_points;
    envelope["relabelled_specks"] = e.relabelled_specks;
    envelope["faces"] = e.faces;
    envelope["reduced_faces"] = e.reduced_faces;
    envelope["distance_max"] = e.distance_max;
    envelope["distance_rms"] = e.distance_rms;
    envelope["bound"] = e.bound;
    envelope["samples_over_bound"] = e.samples_over_bound;
    envelope["places"] = nlohmann::ordered_json::array();
    for (const RepairPlace& p : e.places)
      envelope["places"].push_back({{"point", {p.point.x(), p.point.y(), p.point.z()}}, {"distance", p.distance}});
    envelope["time_seconds"] = e.seconds;
    json["envelope"] = envelope;
  }
  json["time_seconds"] = result.seconds;
  return json;
}

}  // namespace meshprep
