#include "meshprep/preprocess/repair/repair_parameters.h"

namespace meshprep {

const RepairParameters& repair_parameters() {
  // Above a tenth of the median edge, welding would start to merge the ends of real short edges.
  static const RepairParameters parameters{
      {"weld_tolerance", "--weld-tolerance",
       "vertices closer than this fraction of the median edge length are welded into one; 0 = exact copies only",
       {0, 0.1}}};
  return parameters;
}

}  // namespace meshprep
