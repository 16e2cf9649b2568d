#include "meshprep/preprocess/local_height_map.h"

namespace meshprep {

LocalSurfacePoint fit_local_surface(const std::vector<Vec3>& neighbours, const Vec3& x,
                                    HeightMapPolynomial polynomial) {
  LocalSurfacePoint result;
  result.frame = pca_frame(neighbours);
  result.surface_variation = result.frame.surface_variation();

  std::vector<Eigen::Vector2d> sites;
  sites.reserve(neighbours.size());
  Eigen::VectorXd heights(static_cast<Eigen::Index>(neighbours.size()));
  for (std::size_t j = 0; j < neighbours.size(); ++j) {
    const Vec3 local = result.frame.to_local(neighbours[j]);
    sites.emplace_back(local.x(), local.y());
    heights[static_cast<Eigen::Index>(j)] = local.z();
  }
  const HeightMapSpline height_map(sites, heights, polynomial);
  result.bending_energy = height_map.bending_energy();

  Vec3 local = result.frame.to_local(x);
  local.z() = height_map.evaluate(local.x(), local.y());
  result.point = result.frame.to_world(local);
  return result;
}

Vec3 project_to_local_surface(const std::vector<Vec3>& neighbours, const Vec3& x, HeightMapPolynomial polynomial) {
  return fit_local_surface(neighbours, x, polynomial).point;
}

}  // namespace meshprep
