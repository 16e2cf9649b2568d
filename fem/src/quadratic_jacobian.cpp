#include "quadratic_jacobian.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace meshprep::detail {
namespace {

// For each corner c, the three other corners in an order that keeps det positive for a positive
// tet: (0 1 2 3) -> (c a b d) is an even permutation, so det(D_ca, D_cb, D_cd) = det J.
constexpr int kFrames[4][3] = {{1, 2, 3}, {2, 0, 3}, {0, 1, 3}, {0, 2, 1}};

// The node of edge (i, j), i != j, among the ten.
int edge_node(int i, int j) {
  for (int e = 0; e < 6; ++e)
    if ((kTetEdges[e][0] == i && kTetEdges[e][1] == j) || (kTetEdges[e][0] == j && kTetEdges[e][1] == i)) return 4 + e;
  return -1;
}

// g[k][j] (see the header): G_k = sum_j l_j g[k][j].
std::array<std::array<Vec3, 4>, 4> g_coefficients(const std::array<Vec3, 10>& x) {
  std::array<std::array<Vec3, 4>, 4> g;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j) g[k][j] = j == k ? Vec3(3.0 * x[k]) : Vec3(4.0 * x[edge_node(k, j)] - x[k]);
  return g;
}

// G_k at barycentric point l.
std::array<Vec3, 4> gradients(const std::array<std::array<Vec3, 4>, 4>& g, const std::array<double, 4>& l) {
  std::array<Vec3, 4> G;
  for (int k = 0; k < 4; ++k) G[k] = l[0] * g[k][0] + l[1] * g[k][1] + l[2] * g[k][2] + l[3] * g[k][3];
  return G;
}

// The ten nodes' barycentric coordinates.
std::array<std::array<double, 4>, 10> node_coordinates() {
  std::array<std::array<double, 4>, 10> l{};
  for (int i = 0; i < 4; ++i) l[i][i] = 1;
  for (int e = 0; e < 6; ++e) l[4 + e][kTetEdges[e][0]] = l[4 + e][kTetEdges[e][1]] = 0.5;
  return l;
}

double det(const Vec3& a, const Vec3& b, const Vec3& c) { return a.dot(b.cross(c)); }

}  // namespace

std::array<Vec3, 10> tet_nodes(const TetMesh& mesh, std::size_t t) {
  std::array<Vec3, 10> x;
  const Tetrahedron& c = mesh.tets[t];
  for (int i = 0; i < 4; ++i) x[i] = mesh.points[c[i]];
  for (int e = 0; e < 6; ++e)
    x[4 + e] = mesh.quadratic() ? mesh.points[mesh.tet_edge_nodes[t][e]]
                                : Vec3(0.5 * (x[kTetEdges[e][0]] + x[kTetEdges[e][1]]));
  return x;
}

NodalJacobian nodal_jacobian(const std::array<Vec3, 10>& x) {
  static const std::array<std::array<double, 4>, 10> nodes = node_coordinates();
  const auto g = g_coefficients(x);
  NodalJacobian result{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (const auto& l : nodes) {
    const std::array<Vec3, 4> G = gradients(g, l);
    for (int c = 0; c < 4; ++c) {
      const Vec3 a = G[kFrames[c][0]] - G[c], b = G[kFrames[c][1]] - G[c], d = G[kFrames[c][2]] - G[c];
      const double jacobian = det(a, b, d);  // the same for every c (kFrames)
      // Lengths, not squared lengths: the product (degree 3) stays in range, as in tet_quality.cpp.
      const double lengths = a.norm() * b.norm() * d.norm();
      result.min_scaled = std::min(result.min_scaled, lengths > 0 ? std::sqrt(2.0) * jacobian / lengths : 0.0);
      if (c == 0) result.min = std::min(result.min, jacobian);
    }
  }
  return result;
}

// J's columns are D_k = G_k - G_0 = sum_i l_i a_k[i] (k = 1, 2, 3), linear: a_k[i] is D_k at corner
// i. det J = sum_{i,j,m} l_i l_j l_m det(a_1[i], a_2[j], a_3[m]); a monomial l^K of the multiset
// K = {i, j, m} is (K! / 3!) B_K, B_K the cubic Bernstein polynomial, and 3! / K! ordered triples
// have that multiset: B_K's coefficient is the mean of det over them.
double jacobian_lower_bound(const std::array<Vec3, 10>& x) {
  const auto g = g_coefficients(x);
  std::array<std::array<Vec3, 4>, 4> a;  // a[k][i], k = 1..3 used
  for (int k = 1; k < 4; ++k)
    for (int i = 0; i < 4; ++i) a[k][i] = g[k][i] - g[0][i];
  std::array<double, 64> sum{};
  std::array<int, 64> count{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int m = 0; m < 4; ++m) {
        // The multiset's key: its counts of 0, 1, 2, 3 in base 4 (a sparse index, 20 of 64 used).
        std::array<int, 4> counts{};
        ++counts[i], ++counts[j], ++counts[m];
        const int key = counts[0] + 4 * counts[1] + 16 * counts[2];
        sum[key] += det(a[1][i], a[2][j], a[3][m]);
        ++count[key];
      }
  double lowest = std::numeric_limits<double>::infinity();
  for (int key = 0; key < 64; ++key)
    if (count[key] > 0) lowest = std::min(lowest, sum[key] / count[key]);
  return lowest;
}

double straight_jacobian(const std::array<Vec3, 10>& x) { return det(x[1] - x[0], x[2] - x[0], x[3] - x[0]); }

}  // namespace meshprep::detail
