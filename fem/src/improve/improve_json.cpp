// How a tet improvement run is written: the note on a limit the surface sets, and the JSON record.
#include "meshprep/fem/improve_tets.h"

#include "meshprep/quality/json_values.h"
#include "meshprep/report/number_format.h"

#include <nlohmann/json.hpp>

#include <string>

namespace meshprep {

std::string surface_limit_note(const ImproveResult& r, double threshold_deg) {
  if (r.limiting_edges.empty() || r.surface_bound_deg >= threshold_deg) return {};
  const LimitingBoundaryEdge& e = r.limiting_edges.front();
  const auto number = [](double v) { return format_number(v, 4); };
  return "the surface itself allows at most " + number(r.surface_bound_deg) + " deg: " +
         std::to_string(r.limiting_edge_count) + " boundary edge(s) too sharp, the first at (" + number(e.midpoint.x()) +
         ", " + number(e.midpoint.y()) + ", " + number(e.midpoint.z()) + ") with an interior angle of " +
         number(e.interior_angle_deg) + " deg";
}

nlohmann::ordered_json to_json(const ImproveResult& r) {
  nlohmann::ordered_json limiting = nlohmann::ordered_json::array();
  for (const LimitingBoundaryEdge& e : r.limiting_edges)
    limiting.push_back({{"points", {e.a, e.b}},
                        {"midpoint", {e.midpoint.x(), e.midpoint.y(), e.midpoint.z()}},
                        {"interior_angle_deg", e.interior_angle_deg},
                        {"bound_deg", e.bound_deg}});
  return {{"min_dihedral_before_deg", r.min_dihedral_before_deg},
          {"max_dihedral_before_deg", r.max_dihedral_before_deg},
          {"min_dihedral_after_deg", r.min_dihedral_after_deg},
          {"max_dihedral_after_deg", r.max_dihedral_after_deg},
          {"below_goal_before", r.below_goal_before},
          {"below_goal_after", r.below_goal_after},
          {"tets_before", r.tets_before},
          {"tets_after", r.tets_after},
          {"edge_removals", r.edge_removals},
          {"multi_face_removals", r.multi_face_removals},
          {"vertex_moves", r.vertex_moves},
          {"compound_moves", r.compound_moves},
          {"contractions", r.contractions},
          {"inserted_vertices", r.inserted_vertices},
          {"boundary_vertex_moves", r.boundary_vertex_moves},
          {"boundary_max_displacement_relative", r.boundary_max_displacement_relative},
          {"flat_boundary_tets_removed", r.flat_boundary_tets_removed},
          {"passes", r.passes},
          {"stopped_by", r.stopped_by},
          {"seconds", r.seconds},
          {"surface_bound_deg", r.surface_bound_deg},
          {"limiting_edge_count", r.limiting_edge_count},
          {"limiting_edges", limiting},
          {kGuardsTakenBackKey, json_taken_back(r.taken_back)}};
}

}  // namespace meshprep
