#pragma once
/// \file local_frame.h
/// The local frame of a point neighbourhood from principal component analysis (Hoppe et al., as
/// used in Sections 3 and 4 of the paper): the eigenvectors of the 3x3 covariance matrix of the
/// points give the average plane (the two largest eigenvalues) and the normal (the smallest one),
/// and the eigenvalues give the surface variation sigma, the paper's analogue of curvature.

#include "meshprep/core/mesh.h"

#include <vector>

namespace meshprep {

/// An orthonormal, right-handed frame centred on a point set.
struct LocalFrame {
  /// Centroid of the points.
  Vec3 origin = Vec3::Zero();
  /// Columns t1, t2, normal: t1 is the direction of largest variance (eigenvalue lambda3), the
  /// normal the direction of smallest variance (lambda1), t2 = normal x t1 (so det(axes) = +1).
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  /// Eigenvalues of the covariance (1/N) sum (p - c)(p - c)^T, ascending: lambda1 <= lambda2 <=
  /// lambda3 (round-off negatives are clamped to 0: the matrix is positive semi-definite).
  Vec3 eigenvalues = Vec3::Zero();

  /// The paper's surface variation sigma = lambda1 / (lambda1 + lambda2 + lambda3): 0 for points on
  /// a plane, 1/3 for an isotropic cloud (0 when all points coincide).
  double surface_variation() const;
  Vec3 normal() const { return axes.col(2); }
  /// Coordinates of a world point in the frame: (t1, t2, normal) components of p - origin.
  Vec3 to_local(const Vec3& p) const { return axes.transpose() * (p - origin); }
  /// Inverse of to_local.
  Vec3 to_world(const Vec3& q) const { return origin + axes * q; }
};

/// PCA frame of the points (Eigen::SelfAdjointEigenSolver on the covariance about the centroid).
/// The sign of the normal is arbitrary. \throws InvalidInput if points is empty.
LocalFrame pca_frame(const std::vector<Vec3>& points);

/// As pca_frame, with the normal flipped (together with t2, keeping the frame right-handed) so that
/// normal . orientation >= 0.
LocalFrame pca_frame(const std::vector<Vec3>& points, const Vec3& orientation);

}  // namespace meshprep
