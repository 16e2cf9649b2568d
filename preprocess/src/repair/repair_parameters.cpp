#include "meshprep/preprocess/repair/repair_parameters.h"

#include <limits>

namespace meshprep {

const RepairParameters& repair_parameters() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  // Above a tenth of the median edge, welding would start to merge the ends of real short edges.
  static const RepairParameters parameters{
      {"weld_tolerance", "--weld-tolerance",
       "vertices on open edges closer than this fraction of the median edge length are welded into one (exact "
       "copies everywhere; a closed input only at those); 0 = exact copies only",
       {0, 0.1}},
      // No length tells a sheet's outline from a solid's missing part: a flat sheet's outline is
      // at least sqrt 2 x its bounding box's diagonal (a strip's ~2 x, a square terrain's 2.8 x, a
      // hemisphere's rim 2.1 x), and the corpus's scans have openings as long (lion 0.86 and
      // 1.4 x, head 1.0 x, mushroom 2.4 x), which 0.5, the former default, left open. Nor does the
      // flat patch's area against the surface's (lion 0.20, head 0.09, mushroom 0.37; three_peaks
      // 0.48, horizons 0.96). What does is which way the faces turn: a sheet is a height field,
      // every face turned to one side; a solid missing a part has as much surface turned each way
      // but for the part. So by default (auto) every loop is filled but the outline of a component
      // whose one-sidedness (sheet_outlines.h) is above 0.8: the scans measure 0.51 (lion) and
      // less, the terrains (three_peaks, horizons, jacksboro reconstructed) 1.0000, and so does
      // the corpus's holes, a dome: its six holes are filled, its outline is left open. A length
      // given is the override, as before.
      {"max_hole", "--max-hole",
       "boundary loops longer than this fraction of the bounding box's diagonal are left open; auto: every loop is "
       "filled but an open sheet's outline (a component whose faces all turn to one side: a terrain, a mask, a "
       "bowl; not a solid); 0 = fill none",
       {0, inf}},
      {"keep_cavities", "--keep-cavities",
       "keep a closed part lying inside another and touching nothing as the wall of a void, instead of dropping it",
       {}},
      {"route", "--route",
       "how crossing faces are mended: exact (cut along the crossings, keep the union's faces: the surface does not "
       "move), envelope (the solid rebuilt on a grid from the winding number: always a valid solid, moved by up to "
       "about a cell), auto (exact, and envelope where the exact cut leaves crossings or is not done within the time limit)",
       {}},
      // 128: a cell of 1/128 of the longest side, about 4e-3 of a cube's diagonal; the vertices
      // lie on the input, so what moves is the faces between them at sharp edges (a chamfer under
      // half a cell). Time and memory grow with the cube of it: 512 holds 5 bytes for each of
      // 1.4e8 grid points, and the grid's surface of several million faces is simplified after.
      {"envelope_cells", "--envelope-cells",
       "cells of the envelope route's grid across the surface's longest side (finer: closer to the input, slower "
       "by the cube)",
       {8, 512}},
      {"time_limit_seconds", "--repair-time-limit",
       "with route auto, the exact cut must be done this many seconds after the repair began, or the envelope "
       "route rebuilds the solid instead; -1 = automatic, " + parameter_text(kRepairTimeLimitFloorSeconds) + " s + " +
           parameter_text(kRepairTimeLimitPerFaceSeconds * 1e3) + " ms per face; 0 = no limit",
       {-1, inf, false, true}}};
  return parameters;
}

const Choices<RepairRoute>& repair_routes() {
  static const Choices<RepairRoute> routes = {
      {"auto", RepairRoute::automatic}, {"exact", RepairRoute::exact}, {"envelope", RepairRoute::envelope}};
  return routes;
}

}  // namespace meshprep
