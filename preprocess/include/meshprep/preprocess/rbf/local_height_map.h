#pragma once
/// \file local_height_map.h
/// The tangent-frame step of Section 4 of the paper, which places a point on the local surface
/// described by its neighbours (used after the collapse point is found, and by RBF smoothing):
/// 1. the PCA frame of the neighbours (local_frame.h): lambda1 along the normal, the other two
///    eigenvectors span the average plane;
/// 2. rotate the neighbours so that this plane is perpendicular to z: their local coordinates
///    (x_j, y_j, z_j) with z_j the height above the plane;
/// 3. the inverse mapping of eq. (3), z^d = f(P) + z^s: the start surface is the plane (z^s = 0),
///    so f is the thin-plate HeightMapSpline interpolating the heights z_j at (x_j, y_j);
/// 4. the point is moved to the height z^d = f(x, y) at its own local (x, y);
/// 5. the inverse rotation takes it back to world coordinates.
/// The point therefore moves along the frame normal. Planes are reproduced exactly. On a smooth
/// surface sampled at spacing h around the point, the paper's linear polynomial reproduces the
/// plane but not the curvature: the error is O(h^2) (a slight flattening, which smooths; ~0.07 h^2
/// for 20 neighbours on a unit sphere, 1.6e-4 at h = 0.05). HeightMapPolynomial::quadratic
/// reproduces quadrics: O(h^3) in general, O(h^4) observed on the sphere (2e-6 at h = 0.05); it
/// needs two rings of neighbours (see HeightMapPolynomial).

#include "meshprep/core/mesh.h"
#include "meshprep/preprocess/rbf/local_frame.h"
#include "meshprep/preprocess/rbf/thin_plate_spline.h"

#include <vector>

namespace meshprep {

/// Steps 1-3 above for a neighbourhood: its frame and height map, to project any point (step 4-5).
class LocalHeightMap {
 public:
  /// \throws InvalidInput as HeightMapSpline on the neighbours' local (x, y). `smoothing` and
  ///         `weights` (one per neighbour, or none): see HeightMapSpline (smoothing 0 interpolates
  ///         the neighbours). The frame is the unweighted PCA frame of the neighbours.
  explicit LocalHeightMap(const std::vector<Vec3>& neighbours,
                          HeightMapPolynomial polynomial = HeightMapPolynomial::linear, double smoothing = 0,
                          const Eigen::VectorXd& weights = Eigen::VectorXd());
  /// x moved along the frame normal onto the height map.
  Vec3 project(const Vec3& x) const;
  const LocalFrame& frame() const { return frame_; }
  const HeightMapSpline& spline() const { return spline_; }

 private:
  LocalFrame frame_;
  HeightMapSpline spline_;
};

/// The point on the local surface and what was measured on the way.
struct LocalSurfacePoint {
  Vec3 point = Vec3::Zero();     ///< the query moved along the normal onto the height map
  LocalFrame frame;              ///< PCA frame of the neighbours
  double surface_variation = 0;  ///< frame.surface_variation(), the paper's sigma
  double bending_energy = 0;     ///< HeightMapSpline::bending_energy() of the local height map
};

/// Steps 1-5 above. \throws InvalidInput as HeightMapSpline on the neighbours' local (x, y): too
/// few neighbours, two of them coinciding in the plane of the frame, collinear (or, quadratic,
/// on one conic).
LocalSurfacePoint fit_local_surface(const std::vector<Vec3>& neighbours, const Vec3& x,
                                    HeightMapPolynomial polynomial = HeightMapPolynomial::linear, double smoothing = 0);

/// fit_local_surface(neighbours, x, polynomial).point.
Vec3 project_to_local_surface(const std::vector<Vec3>& neighbours, const Vec3& x,
                              HeightMapPolynomial polynomial = HeightMapPolynomial::linear);

}  // namespace meshprep
