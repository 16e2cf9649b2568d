#pragma once
/// \file sliding_landmarks.h
/// Spline relaxation along lines (Section 4 of the paper, after Bookstein 1997, "Landmark methods
/// for forms without landmarks") and the optimal point of an edge collapse derived from it.
///
/// The deformation maps source points X_i (the centres of the volume spline: the union of the two
/// 1-rings of an edge) to target points Y_i, coordinate by coordinate, by three volume splines
/// (eqs. 1-2). Its bending energy is J(Y) = sum over c in {x, y, z} of Y_c^T E Y_c, where Y_c is
/// the column of c-coordinates of the targets and E = volume_spline_energy_matrix(X). E is
/// Bookstein's bending-energy matrix L_N^-1 (the upper-left N x N block of the inverse of the
/// bordered matrix, scaled to the true energy), so the matrix the paper writes L^-1 (L =
/// blockdiag(A, A, A)) is blockdiag(E, E, E): it is E, not A^-1, that gives the energy of the
/// minimum-energy interpolant, and E annihilates affine maps (E X_c = 0), so J(Y) = J(Y - X) and
/// the identity costs nothing.

#include "meshprep/core/mesh.h"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace meshprep {

/// Result of relax_sliding_landmarks.
struct SlidingLandmarks {
  Eigen::VectorXd t;          ///< t_j, one per sliding landmark, in the order given
  std::vector<Vec3> relaxed;  ///< the targets, with Y0_i + t_j u_j at the sliding landmarks
  double bending_energy = 0;  ///< J(relaxed), energy of the map source -> relaxed
};

/// Bookstein's relaxation: landmark sliding[j] of the target may move along directions[j] (u_j;
/// its length sets the unit of t_j; a landmark listed twice slides in a plane); T minimises
/// J(Y0 + U T), i.e. T = -(U^T L^-1 U)^-1 U^T L^-1 Y0 with L^-1 = blockdiag(E, E, E) and U the
/// 3N x k matrix whose column j holds u_j in the rows of landmark sliding[j]. When U^T L^-1 U is
/// singular (a slide that does not change the energy) the minimum-norm T is returned.
///
/// Note: T = 0 whenever target == source (the identity has zero energy), and sliding both end
/// points of an edge independently along the edge from a collapsed target returns them to their
/// source positions. An edge collapse therefore needs the shared parameter of CollapseEnergy.
/// \throws InvalidInput if the sizes differ, an index is out of range, or as VolumeSpline.
SlidingLandmarks relax_sliding_landmarks(const std::vector<Vec3>& source, const std::vector<Vec3>& target,
                                         const std::vector<std::size_t>& sliding,
                                         const std::vector<Vec3>& directions);

/// The bending energy of collapsing edge (a, b) of the centres X to one point on its line,
/// x(s) = P_a + s d with d = P_b - P_a: the target Y(s) is X with Y_a = Y_b = x(s). The
/// displacement is Y(s) - X = w(s) d^T with w(s) = s e_a + (s - 1) e_b, and E X_c = 0, so
///   J(s) = |d|^2 w(s)^T E w(s) = |d|^2 [ s^2 (E_aa + 2 E_ab + E_bb) - 2 s (E_ab + E_bb) + E_bb ],
/// a convex quadratic minimised at s* = (E_ab + E_bb) / (E_aa + 2 E_ab + E_bb). This is the sliding
/// landmark formula above with one parameter shared by both end points (U = one column holding d
/// at a and at b, Y0 = Y(0)). s* depends only on the source geometry; a configuration symmetric
/// under a map swapping a and b (E_aa = E_bb) gives the midpoint.
class CollapseEnergy {
 public:
  /// \throws InvalidInput if a == b, an index is out of range, or as VolumeSpline.
  CollapseEnergy(const std::vector<Vec3>& centres, std::size_t a, std::size_t b);
  /// The same on `count` centres in an array (no heap allocation up to 40 centres).
  CollapseEnergy(const Vec3* centres, std::size_t count, std::size_t a, std::size_t b);

  /// J(s); J(0) collapses onto P_a, J(1) onto P_b.
  double at(double s) const;
  /// The minimiser of J on the edge, s* clamped to [0, 1] (J is convex, so this is the minimum
  /// over the segment); 1/2 when J does not depend on s (e.g. E = 0 for 4 centres).
  double optimal_parameter() const;
  Vec3 point(double s) const { return a_ + s * (b_ - a_); }

 private:
  Vec3 a_, b_;
  double e_aa_ = 0, e_ab_ = 0, e_bb_ = 0;
};

/// The optimal collapse point of edge (a, b) of the centres and its energy.
struct CollapsePoint {
  Vec3 point = Vec3::Zero();
  double s = 0;  ///< point = P_a + s (P_b - P_a), s in [0, 1]
  double bending_energy = 0;
};

/// CollapseEnergy(centres, a, b) at its optimal parameter.
CollapsePoint optimal_collapse_point(const std::vector<Vec3>& centres, std::size_t a, std::size_t b);

}  // namespace meshprep
