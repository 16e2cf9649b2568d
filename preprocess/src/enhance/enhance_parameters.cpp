#include "meshprep/preprocess/enhance/enhance_parameters.h"

#include "meshprep/preprocess/enhance/enhance.h"

#include <limits>

namespace meshprep {

const EnhanceParameters& enhance_parameters() {
  static const std::string largest = parameter_text(EnhanceParams::kLargestAutoDeviation);
  static const EnhanceParameters parameters{
      {"iterations", "--iterations", "rounds at most (statistic, flips, Ceres solve, projection)", {1, 1000}},
      {"max_deviation", "--max-deviation",
       "a face may not move farther than this fraction of the bounding-box diagonal from the reference (unless it "
       "already was); auto: as far as the input already is from the reference (the enhancement is no less faithful "
       "than its input), at most " + largest + ", and " + largest + " when it lies on it",
       {0, 1, true, false}},
      // Every triangle has an angle of at most 60 degrees: a target of 60 would put all in the tail.
      {"target_min_angle_deg", "--target-min-angle",
       "faces with a smaller angle (degrees) are always in the statistic's bad tail", {0, 60, true, true}},
      {"feature_angle_deg", "--feature-angle",
       "edges with a larger dihedral angle (degrees) are creases: their vertices slide only along them; 180 = none",
       {0, 180, true, false}},
      {"flips", "--flips,!--no-flips", "flip edges where moving vertices cannot help", {}},
      {"remesh", "--remesh",
       "remesh first to a sizing field from the surface (curvature, thickness, the input's density): split long "
       "edges, collapse short ones, flip toward valence 6; auto: when the input lies on its reference and more "
       "than " + parameter_text(100 * EnhanceParams::kRemeshAbove) + " % of its faces are under the target angle",
       {}},
      {"max_faces", "--max-faces", "the remeshing's faces at most (the sizing is coarsened to fit); 0: ten times the input's, at least 50000",
       {0, 1e12}},
      {"time_limit_seconds", "--enhance-time-limit",
       "start no round after this many seconds (the best so far is kept); -1 = automatic, " +
           parameter_text(kEnhanceTimeLimitFloorSeconds) + " s + " +
           parameter_text(kEnhanceTimeLimitPerFaceSeconds * 1e3) + " ms per face; 0 = no limit",
       {-1, std::numeric_limits<double>::infinity(), false, true}}};
  return parameters;
}

const Choices<EnhanceRemesh>& enhance_remesh_modes() {
  static const Choices<EnhanceRemesh> modes = {
      {"auto", EnhanceRemesh::Auto}, {"on", EnhanceRemesh::On}, {"off", EnhanceRemesh::Off}};
  return modes;
}

}  // namespace meshprep
