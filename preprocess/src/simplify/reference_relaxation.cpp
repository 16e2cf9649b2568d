#include "simplify/reference_relaxation.h"

#include "shared/triangle_angles.h"
#include "shared/vertex_relaxation.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace meshprep::detail {
namespace {

using VertexHandle = TriMesh::VertexHandle;

const double kTurnCosine = std::cos(60.0 * M_PI / 180.0);
// Tail vertices here have a face over this radius ratio: a margin below the polish's 2.0, so the
// faces just under the goal improve too (radius ratio p95 with 2.0 / 1.9: fandisk at 30 % 1.996 /
// 1.990, bunny00 at 10 % 1.93 / 1.88).
constexpr double kTailMargin = 0.95;
constexpr double kSmallestFraction = 0.1;  // of the way to the centroid: a = 1, 1/2, 1/4, 1/8
constexpr double kFarFromSurface = 0.25;   // of the longest edge: the target left the surface

Vec3 point(const TriMesh& mesh, VertexHandle v) { return to_eigen(mesh.point(v)); }

// Whether the surface at the hit faces the way the vertex does: not the other sheet of a thin
// part (a plate 0.002 thick simplified to 10 %: its vertices went through to the other side).
bool same_side(const TriangleBvh& reference, const TriangleBvh::Hit& hit, const Vec3& normal) {
  const Triangle& t = reference.surface().triangles[hit.face];
  const PointSpan& p = reference.surface().points;
  return area_normal(p[t[0]], p[t[1]], p[t[2]]).dot(normal) > 0;
}

// Calls `sample(p)` for the samples of v's faces with v at `at` (each face's centroid and the
// midpoint of its edge at v) until it returns false; whether none did.
template <class Sample>
bool each_sample(const TriMesh& mesh, VertexHandle v, const Vec3& at, const Sample& sample) {
  for (const auto h : mesh.voh_range(v)) {
    if (mesh.is_boundary(h)) continue;
    const Vec3 b = point(mesh, mesh.to_vertex_handle(h));
    const Vec3 c = point(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h)));
    if (!sample(Vec3(0.5 * (at + b))) || !sample(Vec3((at + b + c) / 3.0))) return false;
  }
  return true;
}

}  // namespace

std::size_t relax_on_reference(TriMesh& mesh, const TriangleBvh& reference, double tolerance, double min_angle_cosine,
                               const HeightField& field) {
  const ShapeTail tail{kTailMargin * ShapeTail().ratio, min_angle_cosine};
  std::size_t moves = 0;
  std::vector<Vec3> ring;
  const FacePatches patches(mesh);
  for (const VertexHandle v : mesh.vertices()) {
    if (!relaxable(mesh, v, patches) || !in_tail(mesh, v, tail)) continue;
    const std::optional<TangentialMove> relax = tangential_move(mesh, v);
    if (!relax || on_feature(mesh, v, ring)) continue;
    const TriangleBvh::Hit here = reference.closest_point(relax->from);
    if (!same_side(reference, here, relax->normal)) continue;
    const double offset = relax->normal.dot(relax->from - here.point);
    const double ratio_before = worst_radius_ratio(mesh, v, relax->from);
    std::optional<double> bound;  // squared: the farthest sample's distance before, at least the tolerance
    for (double fraction = 1; fraction > kSmallestFraction; fraction *= 0.5) {
      const Vec3 target = relax->from + fraction * (relax->to - relax->from);
      const TriangleBvh::Hit on_surface = reference.closest_point(target);
      if ((on_surface.point - target).norm() > kFarFromSurface * relax->reach ||
          !same_side(reference, on_surface, relax->normal))
        continue;
      const Vec3 y = on_surface.point + offset * relax->normal;
      const VertexMove move = vertex_move(mesh, v, y, kTurnCosine, field);
      if (move.turns || !(worst_radius_ratio(mesh, v, y) < ratio_before) ||
          move.new_cosine > std::max(min_angle_cosine, move.old_cosine))
        continue;
      if (!bound) {  // only a sample beyond the bound so far needs its exact distance
        double farthest = tolerance * tolerance;
        each_sample(mesh, v, relax->from, [&](const Vec3& p) {
          if (!reference.reaches_within(p, farthest)) farthest = reference.closest_point(p).squared_distance;
          return true;
        });
        bound = farthest;
      }
      const auto near = [&](const Vec3& p) { return reference.reaches_within(p, *bound); };
      if (!each_sample(mesh, v, y, near)) continue;
      mesh.set_point(v, to_openmesh(y));
      ++moves;
      break;
    }
  }
  return moves;
}

}  // namespace meshprep::detail
