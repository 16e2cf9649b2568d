#include "tet_objective.h"

#include <cmath>

namespace meshprep::improve {
namespace {

// The pieces both functions need: edges, outward area vectors and their lengths.
struct TetGeometry {
  Vec3 e01, e02, e03, e12, e13, e23;
  Vec3 n[4];  // outward area vectors of the faces opposite p0..p3 (for a positive tet)
  double area[4];
  double six_volume;

  TetGeometry(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3)
      : e01(p1 - p0), e02(p2 - p0), e03(p3 - p0), e12(p2 - p1), e13(p3 - p1), e23(p3 - p2) {
    n[0] = e12.cross(e13);
    n[1] = e03.cross(e02);
    n[2] = e01.cross(e03);
    n[3] = e02.cross(e01);
    for (int k = 0; k < 4; ++k) area[k] = n[k].norm();
    six_volume = e01.dot(e02.cross(e03));
  }
  // Faces k < l meet at the edge through the two other corners.
  const Vec3& edge(int k, int l) const {
    if (k == 0) return l == 1 ? e23 : l == 2 ? e13 : e12;
    if (k == 1) return l == 2 ? e03 : e02;
    return e01;
  }
  double squared_edges() const {
    return e01.squaredNorm() + e02.squaredNorm() + e03.squaredNorm() + e12.squaredNorm() + e13.squaredNorm() +
           e23.squaredNorm();
  }
};

}  // namespace

double biased_min_sine(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, double obtuse_weight) {
  const TetGeometry g(p0, p1, p2, p3);
  if (!(g.six_volume > 0)) {
    const double edges = g.squared_edges();
    return edges > 0 ? g.six_volume / (edges * std::sqrt(edges)) : 0.0;
  }
  double worst = 1;
  for (int k = 0; k < 4; ++k)
    for (int l = k + 1; l < 4; ++l) {
      double sine = g.six_volume * g.edge(k, l).norm() / (g.area[k] * g.area[l]);
      if (g.n[k].dot(g.n[l]) > 0) sine *= obtuse_weight;
      if (sine < worst) worst = sine;
    }
  return worst;
}

ObjectiveWithGradient biased_min_sine_gradient(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3,
                                               double obtuse_weight) {
  const TetGeometry g(p0, p1, p2, p3);
  // d(6V)/dp3 = e01 x e02 (6V = (e01 x e02) . e03).
  const Vec3 volume_gradient = g.e01.cross(g.e02);
  if (!(g.six_volume > 0)) {
    const double edges = g.squared_edges();
    if (!(edges > 0)) return {0.0, Vec3::Zero()};
    const Vec3 edges_gradient = 2.0 * (g.e03 + g.e13 + g.e23);
    const double root = std::sqrt(edges);
    return {g.six_volume / (edges * root),
            volume_gradient / (edges * root) - 1.5 * g.six_volume / (edges * edges * root) * edges_gradient};
  }
  int worst_k = 0, worst_l = 1;
  double worst = 2;
  for (int k = 0; k < 4; ++k)
    for (int l = k + 1; l < 4; ++l) {
      double sine = g.six_volume * g.edge(k, l).norm() / (g.area[k] * g.area[l]);
      if (g.n[k].dot(g.n[l]) > 0) sine *= obtuse_weight;
      if (sine < worst) worst = sine, worst_k = k, worst_l = l;
    }
  // The gradient of log |n_k| for the faces through p3 (n_k linear in p3), of log |e| for the
  // edges at p3; the face opposite p3 and the other edges are fixed.
  auto log_area_gradient = [&](int k) -> Vec3 {
    const double a2 = g.area[k] * g.area[k];
    switch (k) {
      case 0: return g.n[0].cross(g.e12) / a2;  // n0 = e12 x (p3 - p1)
      case 1: return g.e02.cross(g.n[1]) / a2;  // n1 = (p3 - p0) x e02
      case 2: return g.n[2].cross(g.e01) / a2;  // n2 = e01 x (p3 - p0)
      default: return Vec3::Zero();
    }
  };
  const Vec3& e = g.edge(worst_k, worst_l);
  Vec3 log_edge_gradient = Vec3::Zero();
  if (&e == &g.e03 || &e == &g.e13 || &e == &g.e23) log_edge_gradient = e / e.squaredNorm();
  const Vec3 log_gradient = volume_gradient / g.six_volume + log_edge_gradient - log_area_gradient(worst_k) -
                            log_area_gradient(worst_l);
  return {worst, worst * log_gradient};
}

}  // namespace meshprep::improve
