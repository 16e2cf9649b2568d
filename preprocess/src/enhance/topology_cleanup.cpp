#include "enhance/topology_cleanup.h"

#include "enhance/reference_cover.h"

#include "shared/triangle_angles.h"

#include "meshprep/quality/triangle_bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace meshprep::detail {
namespace {

using VertexHandle = TriMesh::VertexHandle;

Vec3 point(const TriMesh& mesh, VertexHandle v) { return to_eigen(mesh.point(v)); }

double distance_to_reference(const SurfaceConstraints& constraints, const Vec3& p) {
  return std::sqrt(constraints.closest_on_reference(p).squared_distance);
}

// Whether flipping the edge of h0 sharpens an edge of its quad into a fold with the face beyond
// it. The faces (a, b, c) (normal n0, h0 = a -> b) and (b, a, d) (n1) become (a, d, c) (m0), which
// takes edges c-a and a-d, and (d, b, c) (m1), which takes d-b and b-c.
bool flip_makes_fold(const TriMesh& mesh, TriMesh::HalfedgeHandle h0, const Vec3& n0, const Vec3& n1, const Vec3& m0,
                     const Vec3& m1) {
  const auto h1 = mesh.opposite_halfedge_handle(h0);
  const auto outside = [&](TriMesh::HalfedgeHandle h) { return mesh.opposite_face_handle(h); };
  const std::pair<TriMesh::FaceHandle, std::pair<const Vec3*, const Vec3*>> sides[] = {
      {outside(mesh.prev_halfedge_handle(h0)), {&n0, &m0}}, {outside(mesh.next_halfedge_handle(h1)), {&n1, &m0}},
      {outside(mesh.prev_halfedge_handle(h1)), {&n1, &m1}}, {outside(mesh.next_halfedge_handle(h0)), {&n0, &m1}}};
  for (const auto& [face, normals] : sides) {
    if (!face.is_valid()) continue;
    const Vec3 neighbour = to_eigen(mesh.calc_face_normal(face));
    if (sharpens_into_fold(normal_cosine(*normals.first, neighbour), normal_cosine(*normals.second, neighbour)))
      return true;
  }
  return false;
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
    const Vec3 n0 = area_normal(a, b, c), n1 = area_normal(b, a, d);
    const Vec3 m0 = area_normal(a, d, c), m1 = area_normal(d, b, c);
    if (m0.dot(m1) < cos_max * m0.norm() * m1.norm()) continue;
    if (flip_makes_fold(mesh, h0, n0, n1, m0, m1)) continue;
    // A fold (the two faces turned by more than 90 degrees against each other: a thin wedge that
    // TetGen can only fill with flat tets) is undone when the flip leaves the two faces nearly
    // coplanar and no angle under the target that was not there.
    const bool unfolds = n0.dot(n1) < 0 && after <= std::max(before, rules.min_angle_cosine);
    if (!(after < before - 1e-9) && !unfolds) continue;
    // The local orientation: the normals of every face around a and b (a fold's own two faces
    // nearly cancel).
    Vec3 normal = Vec3::Zero();
    for (const VertexHandle end : {va, vb})
      for (const auto f : mesh.vf_range(end)) normal += to_eigen(mesh.calc_face_normal(f)) * mesh.calc_face_area(f);
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

namespace {

// The halfedge of face f opposite its angle of at least kCapAngleDeg (the cap's long edge, seen
// from the cap); invalid if f is no cap.
TriMesh::HalfedgeHandle cap_long_edge(const TriMesh& mesh, TriMesh::FaceHandle f, double cap_cosine) {
  for (const auto h : mesh.fh_range(f)) {
    const Vec3 a = point(mesh, mesh.from_vertex_handle(h)), b = point(mesh, mesh.to_vertex_handle(h));
    const Vec3 apex = point(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h)));
    if ((a - apex).dot(b - apex) <= cap_cosine * (a - apex).norm() * (b - apex).norm()) return h;
  }
  return TriMesh::HalfedgeHandle();
}

}  // namespace

std::size_t flip_caps(TriMesh& mesh, SurfaceConstraints& constraints, const CleanupRules& rules) {
  const double cap_cosine = std::cos(kCapAngleDeg * M_PI / 180.0);
  std::size_t flips = 0;
  for (const auto f : mesh.faces()) {
    if (mesh.status(f).deleted()) continue;
    const auto h0 = cap_long_edge(mesh, f, cap_cosine);
    if (!h0.is_valid()) continue;
    const auto h1 = mesh.opposite_halfedge_handle(h0);
    const auto e = mesh.edge_handle(h0);
    if (mesh.is_boundary(e) || !mesh.is_flip_ok(e)) continue;
    const VertexHandle va = mesh.from_vertex_handle(h0), vb = mesh.to_vertex_handle(h0);
    if (mesh.valence(va) <= 3 || mesh.valence(vb) <= 3) continue;
    const Vec3 a = point(mesh, va), b = point(mesh, vb);
    const VertexHandle v_apex = mesh.to_vertex_handle(mesh.next_halfedge_handle(h0));
    if (!constraints.is_feature(e) || constraints.role(v_apex) != VertexRole::Surface ||
        constraints.is_feature(mesh.edge_handle(mesh.next_halfedge_handle(h0))) ||
        constraints.is_feature(mesh.edge_handle(mesh.prev_halfedge_handle(h0))))
      continue;
    const Vec3 apex = point(mesh, v_apex);
    const Vec3 d = point(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h1)));
    if (largest_angle_cosine(b, a, d) <= cap_cosine) continue;  // two caps: no normal to trust
    // The faces (a, b, apex) and (b, a, d) become (a, d, apex) and (d, b, apex): the surface
    // moves by at most the apex's distance to the long edge.
    if ((apex - a).cross(b - a).norm() > rules.max_deviation * (b - a).norm()) continue;
    const double before = std::max(smallest_angle_cosine(a, b, apex), smallest_angle_cosine(b, a, d));
    const double after = std::max(smallest_angle_cosine(a, d, apex), smallest_angle_cosine(d, b, apex));
    if (!(after < before - 1e-9)) continue;
    if (largest_angle_cosine(a, d, apex) <= cap_cosine || largest_angle_cosine(d, b, apex) <= cap_cosine) continue;
    const Vec3 n_cap = area_normal(a, b, apex), n_other = area_normal(b, a, d);
    const Vec3 m0 = area_normal(a, d, apex), m1 = area_normal(d, b, apex);
    if (m0.dot(n_other) <= 0 || m1.dot(n_other) <= 0) continue;
    if (flip_makes_fold(mesh, h0, n_cap, n_other, m0, m1)) continue;
    const double old_gap = distance_to_reference(constraints, 0.5 * (a + b));
    if (distance_to_reference(constraints, 0.5 * (apex + d)) > std::max(old_gap, rules.max_deviation)) continue;
    constraints.flip_feature_through_apex(h0);
    ++flips;
  }
  return flips;
}

namespace {

// What collapsing halfedge v -> w (v removed, w kept where it is) does to the faces around v.
struct CollapseEffect {
  bool acceptable = false;
  double new_worst = 1;  // largest smallest-angle cosine of the faces that remain
};

CollapseEffect collapse_effect(const TriMesh& mesh, const SurfaceConstraints& constraints, TriMesh::HalfedgeHandle h,
                               double old_worst, double old_gap, double max_deviation) {
  const VertexHandle v = mesh.from_vertex_handle(h), w = mesh.to_vertex_handle(h);
  const Vec3 x = point(mesh, v), y = point(mesh, w);
  CollapseEffect effect;
  if (constraints.collapse_merges_feature(h)) return effect;
  double nearest_new_face = INFINITY;  // from the removed vertex
  std::vector<Corners> fan_before, fan_after;
  std::vector<std::pair<Vec3, Vec3>> rim;
  for (const auto h_out : mesh.voh_range(v)) {
    const auto f = mesh.face_handle(h_out);
    if (!f.is_valid()) continue;
    Vec3 before[3], after[3];
    int k = 0;
    bool has_w = false;
    for (const VertexHandle u : mesh.fv_range(f)) {
      has_w = has_w || u == w;
      before[k] = point(mesh, u);
      after[k] = u == v ? y : before[k];
      ++k;
    }
    fan_before.push_back({before[0], before[1], before[2]});
    const auto opposite = mesh.next_halfedge_handle(h_out);
    rim.emplace_back(point(mesh, mesh.from_vertex_handle(opposite)), point(mesh, mesh.to_vertex_handle(opposite)));
    if (has_w) continue;  // one of the two faces that vanish
    fan_after.push_back({after[0], after[1], after[2]});
    const Vec3 n0 = area_normal(before[0], before[1], before[2]), n1 = area_normal(after[0], after[1], after[2]);
    if (n0.dot(n1) <= 0.5 * n0.norm() * n1.norm()) return effect;  // turns by more than 60 degrees
    // No new fold across the face's edge opposite v (that neighbour does not move).
    const auto across = mesh.opposite_face_handle(mesh.next_halfedge_handle(h_out));
    if (across.is_valid()) {
      const Vec3 neighbour = to_eigen(mesh.calc_face_normal(across));
      if (sharpens_into_fold(normal_cosine(n0, neighbour), normal_cosine(n1, neighbour))) return effect;
    }
    if (distance_to_reference(constraints, (after[0] + after[1] + after[2]) / 3.0) > std::max(old_gap, max_deviation))
      return effect;
    effect.new_worst = std::max(effect.new_worst == 1 ? -1.0 : effect.new_worst, smallest_angle_cosine(after[0], after[1], after[2]));
    nearest_new_face = std::min(nearest_new_face, (closest_point_on_triangle(x, after[0], after[1], after[2]) - x).norm());
  }
  // No new fold along the edges out of v either: between two faces that both stay, or, where one
  // of them vanishes, between the other and the face that takes its place across (w, p).
  const auto normals = [&](TriMesh::FaceHandle f) {
    Vec3 before[3], after[3];
    int k = 0;
    for (const VertexHandle u : mesh.fv_range(f)) {
      before[k] = point(mesh, u);
      after[k++] = u == v ? y : point(mesh, u);
    }
    return std::make_pair(area_normal(before[0], before[1], before[2]), area_normal(after[0], after[1], after[2]));
  };
  const auto vanishes = [&](TriMesh::FaceHandle f) {
    for (const VertexHandle u : mesh.fv_range(f))
      if (u == w) return true;
    return false;
  };
  for (const auto h_out : mesh.voh_range(v)) {
    const VertexHandle p = mesh.to_vertex_handle(h_out);
    TriMesh::FaceHandle stays = mesh.face_handle(h_out), other = mesh.opposite_face_handle(h_out);
    if (p == w || !stays.is_valid() || !other.is_valid()) continue;
    if (vanishes(stays)) std::swap(stays, other);
    if (vanishes(stays)) continue;
    const auto [kept_before, kept_after] = normals(stays);
    const auto [other_before, other_after] = normals(other);
    Vec3 neighbour_after = other_after;
    if (vanishes(other)) {  // its edge (p, w) joins `stays` to the face across it
      TriMesh::FaceHandle across;
      for (const auto e : mesh.fh_range(other))
        if (mesh.from_vertex_handle(e) != v && mesh.to_vertex_handle(e) != v) across = mesh.opposite_face_handle(e);
      if (!across.is_valid()) continue;
      neighbour_after = to_eigen(mesh.calc_face_normal(across));
    }
    if (sharpens_into_fold(normal_cosine(kept_before, other_before), normal_cosine(kept_after, neighbour_after))) return effect;
  }
  effect.acceptable = nearest_new_face <= max_deviation && effect.new_worst < old_worst &&
                      keeps_reference_covered(constraints, fan_before, fan_after, rim, max_deviation);
  return effect;
}

}  // namespace

std::size_t collapse_for_angles(TriMesh& mesh, const SurfaceConstraints& constraints, const CleanupRules& rules,
                                std::size_t budget) {
  std::size_t removed = 0;
  for (const auto v : mesh.vertices()) {
    if (removed >= budget) break;
    if (mesh.status(v).deleted() || mesh.is_boundary(v) || constraints.role(v) != VertexRole::Surface) continue;
    double old_worst = -1, old_gap = 0;
    for (const auto f : mesh.vf_range(v)) {
      Vec3 p[3];
      int i = 0;
      for (const VertexHandle u : mesh.fv_range(f)) p[i++] = point(mesh, u);
      old_worst = std::max(old_worst, smallest_angle_cosine(p[0], p[1], p[2]));
      old_gap = std::max(old_gap, distance_to_reference(constraints, (p[0] + p[1] + p[2]) / 3.0));
    }
    if (old_worst <= rules.min_angle_cosine) continue;  // every angle around v is good enough
    TriMesh::HalfedgeHandle best;
    double best_worst = old_worst;
    for (const auto h : mesh.voh_range(v)) {
      if (!mesh.is_collapse_ok(h)) continue;
      const CollapseEffect effect = collapse_effect(mesh, constraints, h, old_worst, old_gap, rules.max_deviation);
      if (effect.acceptable && effect.new_worst < best_worst) best_worst = effect.new_worst, best = h;
    }
    if (!best.is_valid()) continue;
    mesh.collapse(best);
    ++removed;
  }
  if (removed > 0) mesh.garbage_collection();
  return removed;
}

// Coplanar: within 0.1 degrees (kCoplanarCosine). With 1 degree the femur's nearly flat spots were
// split as well, and its smallest angle fell from 15.7 to 10.5 degrees (a short edge that the spent
// removal budget left); with 5 degrees TetGen's smallest dihedral on it fell from 5.5 to 4.0.

std::size_t split_for_angles(TriMesh& mesh, SurfaceConstraints& constraints, const CleanupRules& rules,
                             std::size_t budget) {
  std::size_t splits = 0;
  const std::size_t faces = mesh.n_faces();  // the new faces are not looked at in this sweep
  for (std::size_t i = 0; i < faces && splits < budget; ++i) {
    const TriMesh::FaceHandle f(static_cast<int>(i));
    if (mesh.status(f).deleted()) continue;
    TriMesh::HalfedgeHandle longest;
    double longest_length = -1;
    for (const auto h : mesh.fh_range(f)) {
      const double length = (point(mesh, mesh.to_vertex_handle(h)) - point(mesh, mesh.from_vertex_handle(h))).norm();
      if (length > longest_length) longest_length = length, longest = h;
    }
    const auto e = mesh.edge_handle(longest);
    if (mesh.is_boundary(e) || constraints.is_feature(e)) continue;
    const Vec3 a = point(mesh, mesh.from_vertex_handle(longest)), b = point(mesh, mesh.to_vertex_handle(longest));
    const Vec3 c = point(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(longest)));
    const Vec3 d = point(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(mesh.opposite_halfedge_handle(longest))));
    if (smallest_angle_cosine(a, b, c) <= rules.min_angle_cosine) continue;  // f is good enough
    const Vec3 n0 = area_normal(a, b, c), n1 = area_normal(b, a, d);
    if (n0.dot(n1) < kCoplanarCosine * n0.norm() * n1.norm()) continue;
    const Vec3 m = 0.5 * (a + b);
    const double old_worst = std::max(smallest_angle_cosine(a, b, c), smallest_angle_cosine(b, a, d));
    const double new_worst = std::max({smallest_angle_cosine(a, m, c), smallest_angle_cosine(m, b, c),
                                       smallest_angle_cosine(b, m, d), smallest_angle_cosine(m, a, d)});
    if (new_worst > std::max(old_worst, rules.min_angle_cosine) + 1e-12) continue;
    constraints.split_surface_edge(e);
    ++splits;
  }
  return splits;
}

}  // namespace meshprep::detail
