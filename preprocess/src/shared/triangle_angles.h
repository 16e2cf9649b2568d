#pragma once
// Shape tests of the simplifier's guards, polish and fit, of the enhancement's and of the repair's
// patches.

#include "meshprep/core/mesh.h"
#include "meshprep/core/soup_view.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace meshprep::detail {

/// The cosines of the triangle's angles at a, b and c; none for a triangle with a zero-length side.
inline std::optional<std::array<double, 3>> angle_cosines(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, bc = c - b, ca = a - c;
  const double lab = ab.norm(), lbc = bc.norm(), lca = ca.norm();
  if (lab == 0 || lbc == 0 || lca == 0) return std::nullopt;
  return std::array<double, 3>{-ab.dot(ca) / (lab * lca), -bc.dot(ab) / (lbc * lab), -ca.dot(bc) / (lca * lbc)};
}

/// Cosine of the triangle's smallest angle (the largest of its three angle cosines; the smallest
/// angle faces the shortest side); 1 for a triangle with a zero-length side.
inline double smallest_angle_cosine(const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto cosines = angle_cosines(a, b, c);
  return cosines ? std::max({(*cosines)[0], (*cosines)[1], (*cosines)[2]}) : 1.0;
}

/// Cosine of the triangle's largest angle; -1 for a triangle with a zero-length side.
inline double largest_angle_cosine(const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto cosines = angle_cosines(a, b, c);
  return cosines ? std::min({(*cosines)[0], (*cosines)[1], (*cosines)[2]}) : -1.0;
}

/// (b - a) x (c - a): twice the area times the unit normal.
inline Vec3 area_normal(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a); }

/// Unit normal of face `face` of a soup (zero if it is degenerate).
inline Vec3 unit_normal(const SoupView& soup, std::size_t face) {
  const auto& t = soup.triangles[face];
  const Vec3 n = area_normal(soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]);
  return n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
}

/// Whether the edge a-b between triangles (a, b, c) and (b, a, d) is not locally Delaunay: its
/// opposite angles, at c and d, sum to more than pi (beyond rounding), so that flipping it to c-d
/// raises the smaller angles (Lawson's flip).
inline bool flips_to_delaunay(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const auto angle = [](const Vec3& apex, const Vec3& p, const Vec3& q) {
    return std::atan2((p - apex).cross(q - apex).norm(), (p - apex).dot(q - apex));
  };
  return angle(c, a, b) + angle(d, b, a) > M_PI + 1e-12;
}

/// Two faces whose unit normals' cosine exceeds this (0.1 degrees apart) are coplanar: a CAD
/// part's plane; a scan has almost no such pairs (0.5 % of the femur's edges).
inline const double kCoplanarCosine = std::cos(0.1 * M_PI / 180.0);

/// Cosine of the angle between two (area) normals.
inline double normal_cosine(const Vec3& m, const Vec3& n) { return m.dot(n) / (m.norm() * n.norm()); }

/// Whether two faces that share an edge, their normals' cosine going from `before` to `after`,
/// become a fold: the solid's angle along the edge under 15 degrees (the normals opposite within
/// 15 degrees) and smaller than it was. Any tet on such an edge is at least that flat, so the
/// enhancement makes none (an input's own folds may stay, no sharper). Measured on the femur
/// (docs/enhancement.md): 20 degrees cost its smallest face angle (13.3, goal 15), 10 left 8.
inline bool sharpens_into_fold(double before, double after) {
  static const double fold_cosine = -std::cos(15.0 * M_PI / 180.0);
  return after < fold_cosine && after < before;
}

/// A height field's up direction: while it is set, no face may become steeper than the steepest
/// face it had or 60 degrees, whichever is steeper (its normal's cosine with `up` at most
/// `min_cosine`). So a terrain stays one, and a face at its rim meets the block's vertical wall at
/// 30 degrees or more (twice the tet improvement's 15-degree goal: a wedge of alpha allows tets of
/// about alpha / 2 there, docs/tet_improvement.md), or as sharply as the input did. Unset: no rule.
struct HeightField {
  Vec3 up = Vec3::Zero();
  double min_cosine = 0;
  bool keeps(const Vec3& area_normal) const {
    return up == Vec3::Zero() || area_normal.dot(up) > min_cosine * area_normal.norm();
  }
};

/// The HeightField of `mesh` over `up` (unset if `up` is zero): its steepest face's cosine.
inline HeightField height_field_of(const TriMesh& mesh, const Vec3& up) {
  HeightField field;
  if (up == Vec3::Zero()) return field;
  field.up = up.normalized();
  field.min_cosine = 1;
  for (const auto f : mesh.faces()) {
    const auto h = mesh.halfedge_handle(f);
    const Vec3 a = to_eigen(mesh.point(mesh.from_vertex_handle(h))), b = to_eigen(mesh.point(mesh.to_vertex_handle(h))),
               c = to_eigen(mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h))));
    const Vec3 n = area_normal(a, b, c);
    if (n.norm() > 0) field.min_cosine = std::min(field.min_cosine, n.dot(field.up) / n.norm());
  }
  const double sixty_degrees = 0.5;
  field.min_cosine = std::clamp(field.min_cosine, 0.0, sixty_degrees);  // (0: an input fold, none further)
  return field;
}

/// What moving vertex v to `moved_to` does to the faces around it.
struct VertexMove {
  bool turns = false;       ///< a face normal turns by more than the angle whose cosine was given, or over `field`
  double old_cosine = -1;   ///< largest smallest_angle_cosine of the faces before the move
  double new_cosine = -1;   ///< and after (both meaningful only when !turns)
};

inline VertexMove vertex_move(const TriMesh& mesh, TriMesh::VertexHandle v, const Vec3& moved_to, double turn_cosine,
                              const HeightField& field) {
  VertexMove move;
  for (const auto f : mesh.vf_range(v)) {
    Vec3 before[3], after[3];
    int k = 0;
    for (const auto w : mesh.fv_range(f)) {
      before[k] = to_eigen(mesh.point(w));
      after[k] = w == v ? moved_to : before[k];
      ++k;
    }
    const Vec3 n0 = area_normal(before[0], before[1], before[2]), n1 = area_normal(after[0], after[1], after[2]);
    if (n0.dot(n1) <= turn_cosine * n0.norm() * n1.norm() || !field.keeps(n1)) {
      move.turns = true;
      return move;
    }
    move.old_cosine = std::max(move.old_cosine, smallest_angle_cosine(before[0], before[1], before[2]));
    move.new_cosine = std::max(move.new_cosine, smallest_angle_cosine(after[0], after[1], after[2]));
  }
  return move;
}

}  // namespace meshprep::detail
