#include "vertex_smoothing.h"

#include "tet_objective.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace meshprep::improve {
namespace {

// The tet t with corner `slot` free, as (fixed..., free) of the same orientation: each order
// below is an even permutation of t's corners.
OneFreeCornerTet with_free_corner_last(const Tetrahedron& t, int slot, const TetComplex& mesh) {
  switch (slot) {
    case 0: return {{mesh.point(t[1]), mesh.point(t[3]), mesh.point(t[2])}};
    case 1: return {{mesh.point(t[0]), mesh.point(t[2]), mesh.point(t[3])}};
    case 2: return {{mesh.point(t[0]), mesh.point(t[3]), mesh.point(t[1])}};
    default: return {{mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2])}};
  }
}

// A step never goes further than this share of the shortest edge at the vertex.
constexpr double kMaxStepOfShortestEdge = 0.5;

}  // namespace

bool smooth_vertex(TetComplex& mesh, VertexId v, const SlideConstraint* constraint,
                   const std::function<bool(const Vec3&)>& acceptable, int halvings) {
  thread_local std::vector<TetId> star;
  thread_local std::vector<OneFreeCornerTet> tets;
  mesh.star(v, star);
  if (star.empty()) return false;
  tets.clear();
  const Vec3 start = mesh.point(v);
  double shortest = std::numeric_limits<double>::infinity();
  for (const TetId s : star) {
    const Tetrahedron& t = mesh.tet(s);
    for (int c = 0; c < 4; ++c) {
      if (t[c] == v) tets.push_back(with_free_corner_last(t, c, mesh));
      else shortest = std::min(shortest, (mesh.point(t[c]) - start).squaredNorm());
    }
  }
  const double weight = mesh.obtuse_weight();
  const double initial = worst_quality(tets, start, weight);
  MaximisedPosition best =
      maximise_worst_tet(tets, start, kMaxStepOfShortestEdge * std::sqrt(shortest), weight, constraint);
  for (int halving = 0;; ++halving) {
    if (!(best.worst > initial + kMinSineGain)) return false;
    if (all_positive(tets, best.position) && (!acceptable || acceptable(best.position))) break;
    if (halving == halvings) return false;
    Vec3 halfway = start + 0.5 * (best.position - start);
    if (constraint) halfway = constraint->position(halfway);
    best = {halfway, worst_quality(tets, halfway, weight)};
  }
  mesh.move_point(v, best.position, star);
  return true;
}

}  // namespace meshprep::improve
