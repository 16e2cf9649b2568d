#include "meshprep/preprocess/simplify/simplify_parameters.h"

namespace meshprep {

const SimplifyParameters& simplify_parameters() {
  static const SimplifyParameters parameters{
      {"ratio", "--ratio", "fraction of the faces kept", {0, 1, true, false}},
      {"target_faces", "--faces", "target number of faces; 0 = use the ratio", {0, 1e9}},
      {"cost", "--cost",
       "collapse cost: bending (the paper's bending energy as a shape factor on a quadric error memory), "
       "distance (the paper's simple cost: shortest edge first, placed on the local RBF surface) or quadric "
       "(OpenMesh's quadric decimater, the baseline, no shape guard)",
       {}},
      // Every triangle has an angle of at most 60 degrees, so a bound of 60 would refuse all.
      {"min_angle_deg", "--min-angle",
       "collapses may not create a triangle angle under this (degrees) unless the faces around the edge already "
       "had a smaller one; 0 = off",
       {0, 60, false, true}},
      {"max_error", "--max-error",
       "collapses whose estimated deviation exceeds this fraction of the bounding-box diagonal are refused (0 = no "
       "limit; the target may then not be reached)",
       {0, 1}},
      {"polish", "--polish,!--no-polish",
       "flips and relaxation that improve the angles, and the fit to the original, after collapsing", {}}};
  return parameters;
}

const Choices<CollapseCost>& collapse_costs() {
  static const Choices<CollapseCost> costs = {
      {"bending", CollapseCost::Bending}, {"distance", CollapseCost::Distance}, {"quadric", CollapseCost::Quadric}};
  return costs;
}

}  // namespace meshprep
