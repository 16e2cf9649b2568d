#include "meshprep/preprocess/patches/patches_parameters.h"

#include "meshprep/preprocess/patches/patches.h"

namespace meshprep {

const PatchParameters& patch_parameters() {
  static const PatchParameters parameters{
      {"feature_angle_deg", "--feature-angle",
       "edges with a larger dihedral angle (degrees) may border a patch (they must form runs, as the enhancement's "
       "creases); auto: the enhancement's crease angle, " + parameter_text(kDefaultCreaseAngleDeg) + "; 180 = none",
       {0, 180}},
      {"resegment", "--resegment", "segment by the creases even when the file names patches (its names are dropped)", {}},
      {"renames", "--rename", "OLD=NEW: give the patch OLD the name NEW (after the merges)", {}},
      {"merges", "--merge", "A,B,...: the faces of the patches B, ... join the patch A", {}}};
  return parameters;
}

}  // namespace meshprep
