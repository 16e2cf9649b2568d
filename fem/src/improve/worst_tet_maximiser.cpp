#include "worst_tet_maximiser.h"

#include "exact_orientation.h"
#include "tet_objective.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace meshprep::improve {
namespace {

// At most this many iterations; each either gains or ends the climb.
constexpr int kMaxIterations = 12;
// Tets within this of the worst quality form the active set (qualities are sines in [0, 1]).
constexpr double kActiveBand = 1e-3;
// The gradients of at most this many of the worst tets define the search direction.
constexpr std::size_t kMaxActive = 6;
// Step halvings before the line search gives up.
constexpr int kMaxHalvings = 8;


// True if d satisfies the optimality condition of the smallest-norm point of hull(g): every
// g_i . d >= |d|^2 (then no point of the hull is closer to the origin).
bool is_nearest(const std::vector<Vec3>& g, const Vec3& d) {
  const double dd = d.squaredNorm();
  for (const Vec3& gi : g)
    if (gi.dot(d) < dd * (1 - 1e-9)) return false;
  return true;
}

// The point of smallest norm in the convex hull of g (at most kMaxActive points in 3D): by
// Caratheodory it lies in the relative interior of a face spanned by at most three of them, so
// every vertex, edge and triangle is tried; none qualifies only when the hull holds the origin.
Vec3 nearest_point_of_hull(const std::vector<Vec3>& g) {
  Vec3 best = Vec3::Zero();
  double best_norm = std::numeric_limits<double>::infinity();
  auto consider = [&](const Vec3& d) {
    if (d.squaredNorm() < best_norm && is_nearest(g, d)) best = d, best_norm = d.squaredNorm();
  };
  const std::size_t n = g.size();
  for (std::size_t i = 0; i < n; ++i) consider(g[i]);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec3 e = g[j] - g[i];
      const double ee = e.squaredNorm();
      if (ee <= 0) continue;
      const double s = -g[i].dot(e) / ee;
      if (s > 0 && s < 1) consider(g[i] + s * e);
    }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        // min |g_i + s e1 + t e2|^2: the 2x2 normal equations.
        const Vec3 e1 = g[j] - g[i], e2 = g[k] - g[i];
        const double a11 = e1.dot(e1), a12 = e1.dot(e2), a22 = e2.dot(e2);
        const double b1 = -g[i].dot(e1), b2 = -g[i].dot(e2);
        const double det = a11 * a22 - a12 * a12;
        if (!(det > 1e-14 * a11 * a22)) continue;
        const double s = (b1 * a22 - b2 * a12) / det, t = (a11 * b2 - a12 * b1) / det;
        if (s > 0 && t > 0 && s + t < 1) consider(g[i] + s * e1 + t * e2);
      }
  return std::isfinite(best_norm) ? best : Vec3::Zero();
}

}  // namespace

double worst_quality(const std::vector<OneFreeCornerTet>& tets, const Vec3& x, double obtuse_weight) {
  double worst = std::numeric_limits<double>::infinity();
  for (const OneFreeCornerTet& t : tets)
    worst = std::min(worst, biased_min_sine(t.fixed[0], t.fixed[1], t.fixed[2], x, obtuse_weight));
  return worst;
}

MaximisedPosition maximise_worst_tet(const std::vector<OneFreeCornerTet>& tets, const Vec3& start, double max_step,
                                     double obtuse_weight, const SlideConstraint* constraint) {
  MaximisedPosition at{start, worst_quality(tets, start, obtuse_weight)};
  std::vector<double> values(tets.size());
  std::vector<Vec3> gradients(tets.size());
  std::vector<std::size_t> order(tets.size());
  std::vector<Vec3> active;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    for (std::size_t i = 0; i < tets.size(); ++i) {
      const ObjectiveWithGradient q =
          biased_min_sine_gradient(tets[i].fixed[0], tets[i].fixed[1], tets[i].fixed[2], at.position, obtuse_weight);
      values[i] = q.value;
      gradients[i] = constraint ? constraint->direction(q.gradient) : q.gradient;
    }
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    const std::size_t n_active = std::min(kMaxActive, order.size());
    std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n_active), order.end(),
                      [&](std::size_t i, std::size_t j) { return values[i] < values[j]; });
    const double worst = values[order[0]];
    active.clear();
    for (std::size_t k = 0; k < n_active && values[order[k]] <= worst + kActiveBand; ++k) active.push_back(gradients[order[k]]);
    const Vec3 d = nearest_point_of_hull(active);
    const double dd = d.squaredNorm();
    if (!(dd > 0)) break;  // no direction improves every active tet: a local optimum
    // Linearised, the active tets gain dd per unit step and tet i gains g_i . d: the step at
    // which the first other tet would catch up with them.
    double step = max_step / std::sqrt(dd);
    for (std::size_t i = 0; i < tets.size(); ++i) {
      const double rate = gradients[i].dot(d);
      if (values[i] > worst + kActiveBand && rate < dd) step = std::min(step, (values[i] - worst) / (dd - rate));
    }
    bool gained = false;
    for (int halving = 0; halving < kMaxHalvings && !gained; ++halving, step *= 0.5) {
      const Vec3 candidate = constraint ? constraint->position(at.position + step * d) : Vec3(at.position + step * d);
      const double value = worst_quality(tets, candidate, obtuse_weight);
      if (value > at.worst) at = {candidate, value}, gained = true;
    }
    if (!gained) break;
  }
  return at;
}

bool all_positive(const std::vector<OneFreeCornerTet>& tets, const Vec3& x) {
  for (const OneFreeCornerTet& t : tets)
    if (!positively_oriented(t.fixed[0], t.fixed[1], t.fixed[2], x)) return false;
  return true;
}

}  // namespace meshprep::improve
