#include "meshprep/preprocess/smooth/smooth_parameters.h"

#include <limits>

namespace meshprep {

const SmoothParameters& smooth_parameters() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  static const SmoothParameters parameters{
      {"method", "--method",
       "the method: rbf (the paper's: each vertex onto the local RBF surface of its neighbours on its side of any feature), "
       "taubin or laplace (baselines)",
       {}},
      {"iterations", "--iterations", "smoothing iterations", {1, 1000}},
      // The local cubic height map has 10 terms: 13 neighbours leave it overdetermined.
      {"neighbors", "--neighbors", "rbf: neighbours of each vertex's local surface", {13, 200}},
      {"smoothing", "--smoothing",
       "rbf: lambda of the weighted thin-plate smoothing spline; inf, its limit, is the weighted least-squares cubic "
       "(0 interpolates the neighbours)",
       {0, inf}},
      {"relaxation", "--relaxation",
       "rbf: how far each vertex goes towards its 1-ring's centroid before it is put on its local surface (evens "
       "out the triangles; 0 = along the normal only)",
       {0, 1}},
      {"feature_angle_deg", "--feature-angle",
       "rbf: edges with a larger dihedral angle (degrees) are creases, kept sharp; 180 = none", {0, 180, true, false}},
      {"adaptive", "--adaptive,!--no-adaptive",
       "rbf: each vertex moves as far as the noise the mesh shows makes worthwhile, onto a 4-ring or a "
       "2-ring fit, or stays (never more than 2 noise levels along its normal); --no-adaptive moves every "
       "vertex onto its 4-ring fit",
       {}},
      {"preserve_volume", "--preserve-volume",
       "closed surfaces: offset the result along its normals so that the enclosed volume is unchanged", {}}};
  return parameters;
}

const Choices<SmoothMethod>& smooth_methods() {
  static const Choices<SmoothMethod> methods = {
      {"rbf", SmoothMethod::Rbf}, {"taubin", SmoothMethod::Taubin}, {"laplace", SmoothMethod::Laplace}};
  return methods;
}

}  // namespace meshprep
