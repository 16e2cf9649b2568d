// Surface variation per vertex: PCA of each vertex's 2-ring (surface_variation.h).
#include "meshprep/quality/surface_variation.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <limits>

namespace meshprep {
namespace {

// The distinct vertices joined to each vertex by a triangle edge.
std::vector<std::vector<std::uint32_t>> edge_neighbours(const TriangleSoup& soup) {
  std::vector<std::vector<std::uint32_t>> neighbours(soup.points.size());
  for (const Triangle& t : soup.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      if (a == b) continue;
      neighbours[a].push_back(b);
      neighbours[b].push_back(a);
    }
  }
  for (std::vector<std::uint32_t>& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return neighbours;
}

// sigma = lambda1 / (lambda1 + lambda2 + lambda3) of the points `ring` of the soup. The covariance
// is summed about the centroid (two passes), so a far-away origin costs no precision; its scale
// cancels in the ratio.
double variation_of(const std::vector<Vec3>& points, const std::vector<std::uint32_t>& ring) {
  if (ring.size() < 3) return 0.0;
  Vec3 centroid = Vec3::Zero();
  for (const std::uint32_t v : ring) centroid += points[v];
  centroid /= static_cast<double>(ring.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const std::uint32_t v : ring) {
    const Vec3 d = points[v] - centroid;
    covariance.noalias() += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance, Eigen::EigenvaluesOnly);
  const Vec3 lambda = solver.eigenvalues().cwiseMax(0.0);  // ascending; round-off negatives clamped (C is PSD)
  const double total = lambda.sum();
  return total > 0.0 ? lambda[0] / total : 0.0;
}

}  // namespace

std::vector<double> surface_variation(const TriangleSoup& soup) {
  const std::vector<std::vector<std::uint32_t>> neighbours = edge_neighbours(soup);
  std::vector<double> sigma(soup.points.size(), 0.0);
  // last_ring[u] == v once u is in the 2-ring of v: each point enters a ring once.
  std::vector<std::size_t> last_ring(soup.points.size(), std::numeric_limits<std::size_t>::max());
  std::vector<std::uint32_t> ring;
  for (std::size_t v = 0; v < soup.points.size(); ++v) {
    const auto add = [&](std::uint32_t u) {
      if (last_ring[u] == v) return;
      last_ring[u] = v;
      ring.push_back(u);
    };
    ring.clear();
    add(static_cast<std::uint32_t>(v));
    for (const std::uint32_t w : neighbours[v]) add(w);
    const std::size_t one_ring_end = ring.size();
    for (std::size_t i = 1; i < one_ring_end; ++i) {
      for (const std::uint32_t u : neighbours[ring[i]]) add(u);
    }
    sigma[v] = variation_of(soup.points, ring);
  }
  return sigma;
}

}  // namespace meshprep
