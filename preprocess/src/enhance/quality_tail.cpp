#include "enhance/quality_tail.h"

#include "meshprep/core/soup_view.h"
#include "meshprep/quality/triangle_metrics.h"

#include <algorithm>
#include <cmath>

namespace meshprep::detail {
namespace {

struct FaceQuality {
  std::vector<double> q, min_angle_deg;
};

// Per face, in face order (the mesh has no deleted faces): q and the smallest angle, both 0 for a
// degenerate face. The shapes come from the quality module (parallel over faces).
FaceQuality face_quality(const TriMesh& mesh) {
  FaceQuality quality;
  for (const TriangleShape& shape : triangle_shapes(MeshSoupView(mesh))) {
    quality.q.push_back(shape.degenerate ? 0.0 : 1.0 / shape.radius_ratio);
    quality.min_angle_deg.push_back(shape.degenerate ? 0.0 : shape.min_angle_deg);
  }
  return quality;
}

QualityTail summarize(const FaceQuality& quality, double target_min_angle_deg) {
  QualityTail tail;
  const double n = static_cast<double>(quality.q.size());
  if (quality.q.empty()) return tail;
  for (const double q : quality.q) tail.mean_q += q / n;
  for (const double q : quality.q) tail.stddev_q += (q - tail.mean_q) * (q - tail.mean_q) / n;
  tail.stddev_q = std::sqrt(tail.stddev_q);
  std::vector<double> sorted = quality.q;
  const auto p05 = sorted.begin() + static_cast<std::ptrdiff_t>(0.05 * (n - 1));
  std::nth_element(sorted.begin(), p05, sorted.end());
  tail.q_p05 = *p05;
  const auto under = std::count_if(quality.min_angle_deg.begin(), quality.min_angle_deg.end(),
                                   [&](double angle) { return angle < target_min_angle_deg; });
  tail.under_target_fraction = static_cast<double>(under) / n;
  tail.min_angle_deg = *std::min_element(quality.min_angle_deg.begin(), quality.min_angle_deg.end());
  return tail;
}

}  // namespace

QualityTail measure_tail(const TriMesh& mesh, double target_min_angle_deg) {
  return summarize(face_quality(mesh), target_min_angle_deg);
}

std::vector<double> tail_weights(const TriMesh& mesh, const EnhanceParams& params) {
  const FaceQuality quality = face_quality(mesh);
  const QualityTail tail = summarize(quality, params.target_min_angle_deg);
  const double tau = tail.mean_q - params.tail_k * tail.stddev_q;
  std::vector<double> weights(quality.q.size(), 1.0);
  for (std::size_t f = 0; f < weights.size(); ++f) {
    if (tail.stddev_q > 0 && quality.q[f] < tau)
      weights[f] += params.tail_weight * (tau - quality.q[f]) / tail.stddev_q;
    if (quality.min_angle_deg[f] < params.target_min_angle_deg) weights[f] = std::max(weights[f], 1 + params.tail_weight);
  }
  return weights;
}

bool improves(const QualityTail& now, const QualityTail& best, double target_min_angle_deg) {
  const double kept = std::min(best.min_angle_deg, target_min_angle_deg);
  if (kept >= 0.5 * target_min_angle_deg && now.min_angle_deg < kept - 1e-9) return false;
  if (now.under_target_fraction != best.under_target_fraction) return now.under_target_fraction < best.under_target_fraction;
  return now.q_p05 > best.q_p05 + 0.01 * (1 - best.q_p05);
}

}  // namespace meshprep::detail
