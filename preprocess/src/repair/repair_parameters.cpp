#include "meshprep/preprocess/repair/repair_parameters.h"

#include <limits>

namespace meshprep {

const RepairParameters& repair_parameters() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  // Above a tenth of the median edge, welding would start to merge the ends of real short edges.
  static const RepairParameters parameters{
      {"weld_tolerance", "--weld-tolerance",
       "vertices closer than this fraction of the median edge length are welded into one; 0 = exact copies only",
       {0, 0.1}},
      // A flat sheet's outline is at least twice its diameter, so at least sqrt 2 x its bounding
      // box's diagonal (a strip's is ~2 x, a square terrain's 2.8 x, a hemisphere's rim 2.1 x):
      // 0.5 stays far below any sheet's outline and fills the defects of a scan (most of the
      // corpus's holes are 0.05-0.45 x). An opening as large as the part (the corpus's mushroom
      // and holes: 2.4 x) cannot be told from an outline by its length: it takes a --max-hole.
      {"max_hole", "--max-hole",
       "boundary loops longer than this fraction of the bounding box's diagonal are left open (a terrain or a mask "
       "is not a solid); 0 = fill none",
       {0, inf}},
      {"keep_cavities", "--keep-cavities",
       "keep a closed part lying inside another and touching nothing as the wall of a void, instead of dropping it",
       {}}};
  return parameters;
}

}  // namespace meshprep
