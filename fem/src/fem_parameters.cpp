#include "meshprep/fem/fem_parameters.h"

#include "meshprep/fem/improve_tets.h"

#include <limits>

namespace meshprep {

const TetParameters& tet_parameters() {
  static const TetParameters parameters{
      // TetGen's refinement need not end below 1; check_tet_params refuses (0, 1).
      {"radius_edge", "--radius-edge", "TetGen -q bound on circumradius / shortest edge; 0 = no refinement", {0, 100}},
      {"min_dihedral_deg", "--min-dihedral", "TetGen -q target for the smallest dihedral angle (degrees); 0 = TetGen's default",
       {0, 30}},
      {"max_volume_relative", "--max-volume-relative", "largest tet volume / enclosed volume; 0 = no bound", {0, 1}},
      {"keep_surface", "--keep-surface", "the boundary keeps exactly the surface triangles (TetGen -Y)", {}}};
  return parameters;
}

const ImproveParameters& improve_parameters() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  // The regular tet's dihedral angle is 70.5 degrees: a goal must leave room on either side of 60.
  static const ImproveParameters parameters{
      {"tet_quality", "--tet-quality",
       "the goals' preset: default (15/160 deg), high (20/150 deg: climbed from the default's tets, kept only if no "
       "worse; where the surface allows less, the report names the edge), custom (the goals as set)",
       {}},
      {"goal_min_dihedral_deg", "--goal-min-dihedral", "the tets with a smaller dihedral angle (degrees) are improved",
       {0, 60, true, true}},
      {"goal_max_dihedral_deg", "--goal-max-dihedral", "... and those with a larger one (degrees)", {60, 180, true, true}},
      {"insertion", "--insertion", "insert inner vertices where flips and smoothing are stuck", {}},
      {"max_passes", "--max-passes", "passes over the tets below the goal, at most", {1, 1000}},
      {"boundary_deviation", "--boundary-deviation",
       "how far boundary vertices may move the surface, sliding on it where that raises the worst tet, relative to "
       "the diagonal (creases and patch borders kept, corners fixed); 0 = the boundary is kept exactly; auto = 0 in "
       "tetrahedralize and improve, half of what the fidelity bound leaves after the surface stages in the pipeline",
       {0, 1}},
      {"time_limit_seconds", "--improve-time-limit",
       "stop improving after this many seconds (the best tets so far are kept); -1 = automatic, " +
           parameter_text(kAutomaticTimeLimitFloorSeconds) + " s + " +
           parameter_text(kAutomaticTimeLimitPerTetSeconds * 1e6) + " us per tet; 0 = no limit",
       {-1, inf, false, true}}};
  return parameters;
}

const ElementOrderParameters& element_order_parameters() {
  static const ElementOrderParameters parameters{
      {"order", "--order",
       "element order: 1 = linear tets, 2 = 10-node tets whose boundary edges' mid-nodes lie on the surface where "
       "no tet folds",
       {1, 2}}};
  return parameters;
}

const VerdictParameters& verdict_parameters() {
  static const VerdictParameters parameters{
      {"min_dihedral_deg", "--min-dihedral-threshold",
       "FEM-ready only if the tets' smallest dihedral angle is at least this (degrees); 0 = any", {0, 180}},
      {"max_dihedral_deg", "--max-dihedral-threshold",
       "FEM-ready only if the tets' largest dihedral angle is at most this (degrees); 180 = any", {0, 180}},
      {"max_inverted_tets", "--max-inverted-tets",
       "FEM-ready only if at most this many tets are inverted or flat (volume <= 0)", {0, 1000000000}}};
  return parameters;
}

}  // namespace meshprep
