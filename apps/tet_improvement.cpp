#include "tet_improvement.h"

#include "cli_common.h"
#include "interrupt.h"

#include "meshprep/report/number_format.h"

#include <unistd.h>

#include <iostream>
#include <limits>

namespace meshprep::cli {

ImproveResult run_improvement(TetMesh& tets, const ImproveParams& params, nlohmann::ordered_json& json) {
  if (::isatty(STDERR_FILENO))
    std::cerr << "meshprep: improving " << tets.tets.size() << " tets (goal: dihedral angles between "
              << format_number(params.goal_min_dihedral_deg, 4) << " and " << format_number(params.goal_max_dihedral_deg, 4)
              << " deg) ...\n";
  ImproveParams p = params;
  p.cancelled = stop_requested;
  const ImproveResult result = improve_tets(tets, p);
  json["improvement"] = to_json(result);
  note_taken_back(result.taken_back);
  return result;
}

std::string improvement_summary(const ImproveResult& r) {
  std::string line = "smallest dihedral " + format_number(r.min_dihedral_before_deg, 3) + " -> " +
                     format_number(r.min_dihedral_after_deg, 3) + " deg, largest " +
                     format_number(r.max_dihedral_before_deg, 4) + " -> " + format_number(r.max_dihedral_after_deg, 4) +
                     " deg (" + r.stopped_by + ", " + format_number(r.seconds, 3) + " s)";
  if (r.flat_boundary_tets_removed > 0)
    line += "; " + std::to_string(r.flat_boundary_tets_removed) + " flat tet(s) on the boundary removed (its triangles flipped in their plane)";
  const std::string limit = surface_limit_note(r, std::numeric_limits<double>::infinity());
  return limit.empty() ? line : line + "; " + limit;
}

}  // namespace meshprep::cli
