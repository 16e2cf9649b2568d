#include "meshprep/preprocess/rbf/local_height_map.h"

namespace meshprep {
namespace {

HeightMapSpline height_map_in(const LocalFrame& frame, const std::vector<Vec3>& neighbours,
                              HeightMapPolynomial polynomial, double smoothing, const Eigen::VectorXd& weights) {
  std::vector<Eigen::Vector2d> sites;
  sites.reserve(neighbours.size());
  Eigen::VectorXd heights(static_cast<Eigen::Index>(neighbours.size()));
  for (std::size_t j = 0; j < neighbours.size(); ++j) {
    const Vec3 local = frame.to_local(neighbours[j]);
    sites.emplace_back(local.x(), local.y());
    heights[static_cast<Eigen::Index>(j)] = local.z();
  }
  return HeightMapSpline(sites, heights, polynomial, smoothing, weights);
}

}  // namespace

LocalHeightMap::LocalHeightMap(const std::vector<Vec3>& neighbours, HeightMapPolynomial polynomial, double smoothing,
                               const Eigen::VectorXd& weights)
    : frame_(pca_frame(neighbours)), spline_(height_map_in(frame_, neighbours, polynomial, smoothing, weights)) {}

Vec3 LocalHeightMap::project(const Vec3& x) const {
  Vec3 local = frame_.to_local(x);
  local.z() = spline_.evaluate(local.x(), local.y());
  return frame_.to_world(local);
}

LocalSurfacePoint fit_local_surface(const std::vector<Vec3>& neighbours, const Vec3& x,
                                    HeightMapPolynomial polynomial, double smoothing) {
  const LocalHeightMap map(neighbours, polynomial, smoothing);
  LocalSurfacePoint result;
  result.frame = map.frame();
  result.surface_variation = result.frame.surface_variation();
  result.bending_energy = map.spline().bending_energy();
  result.point = map.project(x);
  return result;
}

Vec3 project_to_local_surface(const std::vector<Vec3>& neighbours, const Vec3& x, HeightMapPolynomial polynomial) {
  return fit_local_surface(neighbours, x, polynomial).point;
}

}  // namespace meshprep
