#include "topology_cleanup.h"

#include "triangle_angles.h"

#include <algorithm>
#include <cmath>

namespace meshprep::detail {
namespace {

using VertexHandle = TriMesh::VertexHandle;

Vec3 point(const TriMesh& mesh, VertexHandle v) { return to_eigen(mesh.point(v)); }

double distance_to_reference(const SurfaceConstraints& constraints, const Vec3& p) {
  return std::sqrt(constraints.closest_on_reference(p).squared_distance);
}

}  // namespace

std::size_t flip_for_angles(TriMesh& mesh, const SurfaceConstraints& constraints, const CleanupRules& rules) {
  const double cos_max = std::cos(rules.max_dihedral_deg * M_PI / 180.0);
  std::size_t flips = 0;
  for (const auto e : mesh.edges()) {
    if (mesh.status(e).deleted() || mesh.is_boundary(e) || constraints.is_feature(e) || !mesh.is_flip_ok(e)) continue;
    const auto h0 = mesh.halfedge_handle(e, 0), h1 = mesh.halfedge_handle(e, 1);
    const VertexHandle va = mesh.from_vertex_handle(h0), vb = mesh.to_vertex_handle(h0);
    if (mesh.valence(va) <= 3 || mesh.valence(vb) <= 3) continue;
    const Vec3 a = point(mesh, va), b = point(mesh, vb);
    const Vec3 c = point(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h0)));
    const Vec3 d = point(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h1)));
    // Faces (a, b, c) and (b, a, d) become (a, d, c) and (d, b, c).
    const double before = std::max(smallest_angle_cosine(a, b, c), smallest_angle_cosine(b, a, d));
    const double after = std::max(smallest_angle_cosine(a, d, c), smallest_angle_cosine(d, b, c));
    if (!(after < before - 1e-9)) continue;
    const Vec3 m0 = area_normal(a, d, c), m1 = area_normal(d, b, c);
    if (m0.dot(m1) < cos_max * m0.norm() * m1.norm()) continue;
    const Vec3 normal = area_normal(a, b, c) + area_normal(b, a, d);
    if (m0.dot(normal) <= 0 || m1.dot(normal) <= 0) continue;
    // The flip replaces the tetrahedron's one pair of faces by the other: its height (the two
    // diagonals' midpoints apart along the normal) is how far the surface moves.
    if (std::abs((0.5 * (a + b) - 0.5 * (c + d)).dot((m0 + m1).normalized())) > rules.max_deviation) continue;
    const double old_gap = distance_to_reference(constraints, 0.5 * (a + b));
    if (distance_to_reference(constraints, 0.5 * (c + d)) > std::max(old_gap, rules.max_deviation)) continue;
    mesh.flip(e);
    ++flips;
  }
  return flips;
}

std::size_t remove_valence_three(TriMesh& mesh, const SurfaceConstraints& constraints, const CleanupRules& rules,
                                 std::size_t budget) {
  std::size_t removed = 0;
  for (const auto v : mesh.vertices()) {
    if (removed >= budget) break;
    if (mesh.status(v).deleted() || mesh.is_boundary(v) || mesh.valence(v) != 3 || constraints.role(v) != VertexRole::Surface)
      continue;
    // The ring a, b, c in the order of the faces around v: the new face (a, b, c) keeps their orientation.
    VertexHandle ring[3];
    int k = 0;
    for (const VertexHandle w : mesh.vv_range(v)) ring[k++] = w;
    const Vec3 a = point(mesh, ring[0]), b = point(mesh, ring[1]), c = point(mesh, ring[2]);
    const Vec3 new_normal = area_normal(a, b, c);
    Vec3 old_normal = Vec3::Zero();
    double old_worst = -1, old_gap = 0;
    for (const auto f : mesh.vf_range(v)) {
      Vec3 p[3];
      int i = 0;
      for (const VertexHandle w : mesh.fv_range(f)) p[i++] = point(mesh, w);
      old_normal += area_normal(p[0], p[1], p[2]);
      old_worst = std::max(old_worst, smallest_angle_cosine(p[0], p[1], p[2]));
      old_gap = std::max(old_gap, distance_to_reference(constraints, (p[0] + p[1] + p[2]) / 3.0));
    }
    if (!(smallest_angle_cosine(a, b, c) < old_worst)) continue;
    // The new face takes the old faces' orientation (whatever order vv_range gave a, b, c in); it
    // must not turn by more than 60 degrees from their summed normal (v was no spike).
    if (std::abs(new_normal.dot(old_normal)) < 0.5 * new_normal.norm() * old_normal.norm()) continue;
    if (std::abs((point(mesh, v) - a).dot(new_normal.normalized())) > rules.max_deviation) continue;
    if (distance_to_reference(constraints, (a + b + c) / 3.0) > std::max(old_gap, rules.max_deviation)) continue;
    const auto h = mesh.find_halfedge(v, ring[0]);
    if (!h.is_valid() || !mesh.is_collapse_ok(h)) continue;
    mesh.collapse(h);
    ++removed;
  }
  if (removed > 0) mesh.garbage_collection();
  return removed;
}

}  // namespace meshprep::detail
