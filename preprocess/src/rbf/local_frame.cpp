#include "meshprep/preprocess/rbf/local_frame.h"

#include "meshprep/core/errors.h"

#include <Eigen/Eigenvalues>

namespace meshprep {

double LocalFrame::surface_variation() const {
  const double total = eigenvalues.sum();
  return total > 0 ? eigenvalues.x() / total : 0.0;
}

LocalFrame pca_frame(const std::vector<Vec3>& points) {
  if (points.empty()) throw InvalidInput("no points to fit a plane to");
  LocalFrame frame;
  for (const Vec3& p : points) frame.origin += p;
  frame.origin /= static_cast<double>(points.size());
  // Two passes (centroid first) so that the covariance carries no cancellation from far origins.
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) {
    const Vec3 d = p - frame.origin;
    covariance.noalias() += d * d.transpose();
  }
  covariance /= static_cast<double>(points.size());

  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);  // ascending eigenvalues
  frame.eigenvalues = solver.eigenvalues().cwiseMax(0.0);
  const Vec3 normal = solver.eigenvectors().col(0);
  const Vec3 t1 = solver.eigenvectors().col(2);
  frame.axes.col(0) = t1;
  frame.axes.col(1) = normal.cross(t1);
  frame.axes.col(2) = normal;
  return frame;
}

LocalFrame pca_frame(const std::vector<Vec3>& points, const Vec3& orientation) {
  LocalFrame frame = pca_frame(points);
  if (frame.normal().dot(orientation) < 0) {
    frame.axes.col(1) = -frame.axes.col(1);
    frame.axes.col(2) = -frame.axes.col(2);
  }
  return frame;
}

}  // namespace meshprep
