#include "simplify/collapse_quadrics.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace meshprep::detail {
namespace {

// Relative weight of a boundary's constraint planes: large enough that a boundary vertex slides
// along the boundary curve rather than into the surface (Garland & Heckbert 1997, section 6).
constexpr double kBoundaryWeight = 100.0;
// Eigenvalues of the quadric's 3x3 part below this fraction of the largest are treated as zero.
constexpr double kRankTolerance = 1e-3;

Quadric plane_quadric(const Vec3& unit_normal, const Vec3& point, double weight) {
  Quadric q(unit_normal.x(), unit_normal.y(), unit_normal.z(), -unit_normal.dot(point));
  q *= weight;
  return q;
}

Eigen::Matrix3d linear_part(const Quadric& q) {
  Eigen::Matrix3d a;
  a << q.a(), q.b(), q.c(), q.b(), q.e(), q.f(), q.c(), q.f(), q.h();
  return a;
}

}  // namespace

std::vector<Quadric> vertex_quadrics(const TriMesh& mesh, double unit_length) {
  std::vector<Quadric> quadrics(mesh.n_vertices());
  const double unit_area = unit_length * unit_length;
  for (const auto f : mesh.faces()) {
    auto h = mesh.halfedge_handle(f);
    const Vec3 a = to_eigen(mesh.point(mesh.from_vertex_handle(h)));
    const Vec3 b = to_eigen(mesh.point(mesh.to_vertex_handle(h)));
    const Vec3 c = to_eigen(mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h))));
    const Vec3 n = (b - a).cross(c - a);
    const double twice_area = n.norm();
    if (!(twice_area > 0)) continue;
    const Quadric q = plane_quadric(n / twice_area, a, 0.5 * twice_area / unit_area);
    for (const auto v : mesh.fv_range(f)) quadrics[static_cast<std::size_t>(v.idx())] += q;
  }
  for (const auto h : mesh.halfedges()) {
    if (!mesh.is_boundary(h)) continue;
    const auto inner = mesh.opposite_halfedge_handle(h);
    const auto from = mesh.from_vertex_handle(h), to = mesh.to_vertex_handle(h);
    const Vec3 p = to_eigen(mesh.point(from)), d = to_eigen(mesh.point(to)) - p;
    const auto f = mesh.face_handle(inner);
    auto fh = mesh.halfedge_handle(f);
    const Vec3 a = to_eigen(mesh.point(mesh.from_vertex_handle(fh)));
    const Vec3 b = to_eigen(mesh.point(mesh.to_vertex_handle(fh)));
    const Vec3 c = to_eigen(mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(fh))));
    const Vec3 side = d.cross((b - a).cross(c - a));
    if (!(side.norm() > 0)) continue;
    const Quadric q = plane_quadric(side.normalized(), p, kBoundaryWeight * d.squaredNorm() / unit_area);
    quadrics[static_cast<std::size_t>(from.idx())] += q;
    quadrics[static_cast<std::size_t>(to.idx())] += q;
  }
  return quadrics;
}

double evaluate(const Quadric& q, const Vec3& p) { return std::max(0.0, q(OpenMesh::Vec3d(p.x(), p.y(), p.z()))); }

double rms_plane_distance(const Quadric& q, const Vec3& p) {
  const double weight = q.a() + q.e() + q.h();  // each unit normal contributes |n|^2 = 1 times its weight
  return weight > 0 ? std::sqrt(evaluate(q, p) / weight) : 0.0;
}

Vec3 minimiser_near(const Quadric& q, const Vec3& anchor) {
  const Eigen::Matrix3d a = linear_part(q);
  const Vec3 gradient_half = a * anchor + Vec3(q.d(), q.g(), q.i());  // (1/2) grad Q at the anchor
  // Well conditioned (about half the edges' quadrics on bunny00): the pseudo-inverse is the
  // inverse, and no eigen-solve is needed. The smallest eigenvalue is at least 1 / |A^-1|_F and the
  // largest at most trace(A) (A is positive semidefinite): if the one bound clears the tolerance
  // times the other, every eigenvalue is kept.
  Eigen::Matrix3d inverse;
  double determinant = 0;
  bool invertible = false;
  a.computeInverseAndDetWithCheck(inverse, determinant, invertible);
  if (invertible && determinant > 0 && kRankTolerance * a.trace() * inverse.norm() < 1)
    return anchor - inverse * gradient_half;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(a);
  const Vec3 values = eigen.eigenvalues();
  const double largest = values.cwiseAbs().maxCoeff();
  if (!(largest > 0)) return anchor;
  Vec3 step = Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    if (values[i] <= kRankTolerance * largest) continue;
    const Vec3 axis = eigen.eigenvectors().col(i);
    step -= axis * (axis.dot(gradient_half) / values[i]);
  }
  return anchor + step;
}

}  // namespace meshprep::detail
