#include "simplify/collapse_guard.h"

#include <algorithm>

namespace meshprep::detail {
namespace {

using VertexHandle = TriMesh::VertexHandle;
using HalfedgeHandle = TriMesh::HalfedgeHandle;

// A face whose doubled area is below this fraction of its squared perimeter is degenerate.
constexpr double kDegenerateArea = 1e-10;

}  // namespace

bool collapse_keeps_shape(const TriMesh& mesh, TriMesh::HalfedgeHandle h, const Vec3& p, double min_angle_cosine,
                          const HeightField& field) {
  const VertexHandle removed = mesh.from_vertex_handle(h), kept = mesh.to_vertex_handle(h);
  const auto point = [&mesh](VertexHandle v) { return to_eigen(mesh.point(v)); };
  double old_cosine = -1, new_cosine = -1;
  // Each face once, walked from its corner at an end point (halfedges, not nested circulators:
  // this runs for every collapse tried, refused or not).
  for (const VertexHandle end : {removed, kept}) {
    const VertexHandle other = end == removed ? kept : removed;
    const Vec3 at = point(end);
    for (const HalfedgeHandle out : mesh.voh_range(end)) {
      if (mesh.is_boundary(out)) continue;  // no face on this side
      const VertexHandle b = mesh.to_vertex_handle(out), c = mesh.to_vertex_handle(mesh.next_halfedge_handle(out));
      const bool deleted = b == other || c == other;  // one of the two faces the collapse deletes
      if (deleted && end == kept) continue;          // already seen from `removed`
      const Vec3 pb = point(b), pc = point(c);
      old_cosine = std::max(old_cosine, smallest_angle_cosine(at, pb, pc));
      if (deleted) continue;
      const Vec3 n0 = area_normal(at, pb, pc), n1 = area_normal(p, pb, pc);
      const double perimeter = (pb - p).norm() + (pc - pb).norm() + (p - pc).norm();
      if (!(n1.norm() > kDegenerateArea * perimeter * perimeter)) return false;
      if (n0.dot(n1) <= 0 || !field.keeps(n1)) return false;
      new_cosine = std::max(new_cosine, smallest_angle_cosine(p, pb, pc));
    }
  }
  return new_cosine <= std::max(min_angle_cosine, old_cosine) + 1e-12;
}

}  // namespace meshprep::detail
