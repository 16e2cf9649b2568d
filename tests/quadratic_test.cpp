// Second-order tets: the mid-edge nodes of TetMesh (tet_mesh.h), make_quadratic and
// quadratic_boundary (quadratic.h), and their quality (tet_quality.h).
#include "meshprep/fem/improve_tets.h"
#include "meshprep/fem/quadratic.h"
#include "meshprep/fem/tet_boundary.h"
#include "meshprep/fem/tet_quality.h"
#include "meshprep/fem/tetrahedralize.h"
#include "meshprep/core/errors.h"
#include "quadratic_jacobian.h"
#include "test_meshes.h"
#include "tet_test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <utility>

namespace meshprep {
namespace {

// ---- an independent second-order map, for checks: x(l) from the ten nodes, J by differences ----

Vec3 p2_point(const std::array<Vec3, 10>& x, const std::array<double, 4>& l) {
  Vec3 p = Vec3::Zero();
  for (int i = 0; i < 4; ++i) p += l[i] * (2 * l[i] - 1) * x[i];
  for (int e = 0; e < 6; ++e) p += 4 * l[kTetEdges[e][0]] * l[kTetEdges[e][1]] * x[4 + e];
  return p;
}

// det J at barycentric l, J's columns the derivatives along the reference edges from corner 0
// (central differences: exact up to round-off for a quadratic map).
double p2_jacobian(const std::array<Vec3, 10>& x, const std::array<double, 4>& l) {
  const double h = 1e-4;
  Eigen::Matrix3d j;
  for (int k = 1; k < 4; ++k) {
    std::array<double, 4> plus = l, minus = l;
    plus[k] += h, plus[0] -= h, minus[k] -= h, minus[0] += h;
    j.col(k - 1) = (p2_point(x, plus) - p2_point(x, minus)) / (2 * h);
  }
  return j.determinant();
}

std::array<Vec3, 10> straight_nodes(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  std::array<Vec3, 10> x{a, b, c, d};
  for (int e = 0; e < 6; ++e) x[4 + e] = 0.5 * (x[kTetEdges[e][0]] + x[kTetEdges[e][1]]);
  return x;
}

TetMesh sphere_tets(double radius) {
  TetParams p;
  p.keep_surface = true;  // the boundary is the icosphere's triangles
  return tetrahedralize_plc(plc_from_surface(test::icosphere(2, radius)), p);
}

TetMesh scaled(TetMesh mesh, double s) {
  for (Vec3& p : mesh.points) p *= s;
  return mesh;
}

TriangleSoup scaled(TriangleSoup soup, double s) {
  for (Vec3& p : soup.points) p *= s;
  return soup;
}

// A fine icosphere turned about an oblique axis: the sphere again, but not nested with the
// tets' icosphere, whose edge midpoints would otherwise lie exactly below its vertices, where
// two faces are equally near (a tie round-off breaks either way, differently at each scale).
TriangleSoup sphere_reference(int levels) {
  TriangleSoup soup = test::icosphere(levels);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  for (Vec3& p : soup.points) p = turn * p;
  return soup;
}

// The largest distance of the soup's points from the sphere of `radius` at the origin.
double max_sphere_distance(const TriangleSoup& soup, double radius) {
  double worst = 0;
  for (const Vec3& p : soup.points) worst = std::max(worst, std::abs(p.norm() - radius));
  return worst;
}

// ---- the data model ----

TEST(TetEdges, CanonicalOrderIsVtks) {
  // VTK_QUADRATIC_TETRA: nodes 4..9 on (0,1) (1,2) (0,2) (0,3) (1,3) (2,3).
  const std::array<std::array<int, 2>, 6> vtk{{{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}}};
  EXPECT_EQ(kTetEdges, vtk);
  const Tetrahedron tet{10, 11, 12, 13};
  for (int e = 0; e < 6; ++e) {
    EXPECT_EQ(tet_edge_index(tet, tet[kTetEdges[e][0]], tet[kTetEdges[e][1]]), e);
    EXPECT_EQ(tet_edge_index(tet, tet[kTetEdges[e][1]], tet[kTetEdges[e][0]]), e);
  }
  EXPECT_EQ(tet_edge_index(tet, 10, 14), -1);
}

TEST(TetEdges, FaceEdgeNodesFollowTheFacesCorners) {
  const Tetrahedron tet{0, 1, 2, 3};
  const TetEdgeNodes nodes{4, 5, 6, 7, 8, 9};  // (0,1) (1,2) (0,2) (0,3) (1,3) (2,3)
  EXPECT_EQ(face_edge_nodes(tet, nodes, {1, 2, 3}), (std::array<std::uint32_t, 3>{5, 9, 8}));
  EXPECT_EQ(face_edge_nodes(tet, nodes, {0, 3, 2}), (std::array<std::uint32_t, 3>{7, 9, 6}));
  EXPECT_EQ(face_edge_nodes(tet, nodes, {2, 0, 1}), (std::array<std::uint32_t, 3>{6, 4, 5}));
}

TEST(TetEdges, AggregateInitialisationLeavesTheMeshLinear) {
  const TetMesh mesh{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}, {{0, 1, 2, 3}}, {1}, {}, {}};
  EXPECT_FALSE(mesh.quadratic());
  EXPECT_TRUE(boundary_face_edge_nodes(mesh).empty());
}

TEST(Quadratic, StraightCubeHasOneNodePerEdgeAtItsMidpoint) {
  TetMesh mesh = test::cube_tets(2);
  const std::size_t corners = mesh.points.size();
  const QuadraticResult r = make_quadratic(mesh);
  // A Kuhn-cut cube of n^3 cells: edges on the lattice lines, the face and cell diagonals.
  const int n = 2;
  const std::size_t lattice = 3 * n * (n + 1) * (n + 1), face_diagonals = 3 * n * n * (n + 1), cell_diagonals = n * n * n;
  EXPECT_EQ(r.edges, lattice + face_diagonals + cell_diagonals);
  EXPECT_EQ(mesh.points.size(), corners + r.edges);
  EXPECT_EQ(r.boundary_edges, 6u * (2 * n * (n + 1) + n * n) - 12u * n);  // each face's, minus the cube's edges counted twice
  EXPECT_EQ(r.curved_edges, 0u);
  EXPECT_EQ(r.nonpositive_jacobian_tets, 0u);
  ASSERT_EQ(mesh.tet_edge_nodes.size(), mesh.tets.size());
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> node_of;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (int e = 0; e < 6; ++e) {
      std::uint32_t a = mesh.tets[t][kTetEdges[e][0]], b = mesh.tets[t][kTetEdges[e][1]];
      const std::uint32_t node = mesh.tet_edge_nodes[t][e];
      EXPECT_GE(node, corners);
      EXPECT_EQ(mesh.points[node], 0.5 * (mesh.points[a] + mesh.points[b]));
      if (a > b) std::swap(a, b);
      const auto [it, added] = node_of.emplace(std::make_pair(a, b), node);
      EXPECT_EQ(it->second, node) << "edge " << a << "-" << b << " has two nodes";
    }
  EXPECT_EQ(node_of.size(), r.edges);
  // The boundary faces' nodes are those of their edges.
  const auto mids = boundary_face_edge_nodes(mesh);
  ASSERT_EQ(mids.size(), mesh.boundary_faces.size());
  for (std::size_t f = 0; f < mids.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Vec3 expected = 0.5 * (mesh.points[mesh.boundary_faces[f][k]] + mesh.points[mesh.boundary_faces[f][(k + 1) % 3]]);
      EXPECT_EQ(mesh.points[mids[f][k]], expected);
    }
  // Straight: the P2 figure is Verdict's scaled Jacobian.
  const TetQualityReport q = analyze_tet_quality(mesh);
  ASSERT_TRUE(q.quadratic);
  EXPECT_NEAR(r.min_scaled_jacobian, q.scaled_jacobian.min, 1e-12);
  EXPECT_EQ(q.quadratic->curved_tets, 0u);
  EXPECT_EQ(q.quadratic->nonpositive_jacobian_tets, 0u);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    EXPECT_NEAR(q.quadratic->min_scaled_jacobian_per_tet[t], q.scaled_jacobian_per_tet[t], 1e-12) << "tet " << t;
  // The linear mesh of it is the cube again.
  const TetMesh linear = linear_mesh(mesh);
  const TetMesh cube = test::cube_tets(2);
  EXPECT_EQ(linear.points, cube.points);
  EXPECT_EQ(linear.tets, cube.tets);
  EXPECT_EQ(linear.boundary_faces, cube.boundary_faces);
  EXPECT_FALSE(linear.quadratic());
}

TEST(Quadratic, RefusesWhatItCannotTake) {
  TetMesh mesh = test::cube_tets(1);
  make_quadratic(mesh);
  EXPECT_THROW(make_quadratic(mesh), InvalidInput);  // already second-order
  TetMesh empty;
  EXPECT_THROW(make_quadratic(empty), InvalidInput);
  // The improvement moves linear tets only.
  try {
    improve_tets(mesh);
    FAIL() << "improve_tets took a second-order mesh";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("second-order"), std::string::npos) << e.what();
  }
}

// ---- the Jacobian ----

TEST(QuadraticJacobian, StraightTetGivesVerdictsScaledJacobianAtEveryNode) {
  const Vec3 a(0, 0, 0), b(1, 0.1, 0), c(0.2, 0.9, 0.1), d(0.3, 0.2, 0.7);
  const std::array<Vec3, 10> x = straight_nodes(a, b, c, d);
  EXPECT_NEAR(detail::nodal_jacobian(x).min_scaled, tet_shape(a, b, c, d).scaled_jacobian, 1e-14);
  const double j0 = detail::straight_jacobian(x);
  EXPECT_NEAR(detail::jacobian_lower_bound(x), j0, 1e-14);
  EXPECT_NEAR(detail::nodal_jacobian(x).min, j0, 1e-14);
  // The regular tet: 1.
  const std::array<Vec3, 10> regular =
      straight_nodes(Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, -1, 1), Vec3(-1, 1, -1));
  EXPECT_NEAR(detail::nodal_jacobian(regular).min_scaled, 1.0, 1e-14);
}

// A curved tet: the nodal figures against the independent map, the Bezier bound below det J
// everywhere and equal to it at the corners.
TEST(QuadraticJacobian, CurvedTetAgainstAnIndependentMap) {
  std::array<Vec3, 10> x = straight_nodes(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1));
  x[4] += Vec3(0, -0.15, -0.1);  // edge (0,1) bulges outward
  x[9] += Vec3(0.1, 0.1, 0.1);   // edge (2,3) too
  double nodal = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i) {
    std::array<double, 4> l{};
    l[i] = 1;
    nodal = std::min(nodal, p2_jacobian(x, l));
    EXPECT_GE(p2_jacobian(x, l), detail::jacobian_lower_bound(x) - 1e-9);
  }
  for (const auto& e : kTetEdges) {
    std::array<double, 4> l{};
    l[e[0]] = l[e[1]] = 0.5;
    nodal = std::min(nodal, p2_jacobian(x, l));
  }
  EXPECT_NEAR(detail::nodal_jacobian(x).min, nodal, 1e-9);
  std::mt19937 random(7);
  std::exponential_distribution<double> weight(1.0);
  const double bound = detail::jacobian_lower_bound(x);
  for (int s = 0; s < 2000; ++s) {
    std::array<double, 4> l;
    double sum = 0;
    for (double& v : l) sum += (v = weight(random));
    for (double& v : l) v /= sum;
    EXPECT_GE(p2_jacobian(x, l), bound - 1e-9);
  }
}

// ---- make_quadratic on a sphere ----

TEST(Quadratic, SphereBoundaryMovesOntoTheReferenceAndCloserToTheSphere) {
  TetMesh mesh = sphere_tets(1.0);
  const double linear_error = max_sphere_distance(quadratic_boundary(mesh, 8), 1.0);
  const TriangleSoup reference = sphere_reference(5);
  const QuadraticResult r = make_quadratic(mesh, &reference);
  EXPECT_EQ(r.boundary_edges, 480u);  // icosphere(2): 320 faces, 480 edges
  EXPECT_GT(r.curved_edges, 470u);
  EXPECT_EQ(r.curved_edges + r.on_reference + r.straight_inverting + r.straight_off_reference, r.boundary_edges);
  EXPECT_EQ(r.nonpositive_jacobian_tets, 0u);
  EXPECT_GT(r.min_scaled_jacobian, 0.0);
  const double quadratic_error = max_sphere_distance(quadratic_boundary(mesh, 8), 1.0);
  EXPECT_LT(quadratic_error, linear_error / 5) << linear_error << " -> " << quadratic_error;
  // Every tet valid everywhere: det J sampled inside each curved tet stays above the bound.
  const TetQualityReport q = analyze_tet_quality(mesh);
  ASSERT_TRUE(q.quadratic);
  EXPECT_EQ(q.quadratic->nonpositive_jacobian_tets, 0u);
  EXPECT_GT(q.quadratic->curved_tets, 0u);
  EXPECT_DOUBLE_EQ(q.quadratic->min_scaled_jacobian.min, r.min_scaled_jacobian);
  std::mt19937 random(11);
  std::exponential_distribution<double> weight(1.0);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const std::array<Vec3, 10> x = detail::tet_nodes(mesh, t);
    const double floor = kMinJacobianRatio * detail::straight_jacobian(x) * (1 - 1e-9);
    for (int s = 0; s < 50; ++s) {
      std::array<double, 4> l;
      double sum = 0;
      for (double& v : l) sum += (v = weight(random));
      for (double& v : l) v /= sum;
      ASSERT_GE(p2_jacobian(x, l), floor) << "tet " << t;
    }
  }
}

TEST(Quadratic, ResultsDoNotDependOnUnits) {
  const TetMesh unit = sphere_tets(1.0);
  const TriangleSoup reference = sphere_reference(4);
  TetMesh base = unit;
  const QuadraticResult r1 = make_quadratic(base, &reference);
  for (const double s : {1e-3, 1e3}) {
    TetMesh mesh = scaled(unit, s);
    const TriangleSoup ref = scaled(reference, s);
    const QuadraticResult r = make_quadratic(mesh, &ref);
    EXPECT_EQ(r.curved_edges, r1.curved_edges) << s;
    EXPECT_EQ(r.straight_inverting, r1.straight_inverting) << s;
    EXPECT_EQ(r.straight_off_reference, r1.straight_off_reference) << s;
    EXPECT_NEAR(r.min_scaled_jacobian, r1.min_scaled_jacobian, 1e-9) << s;
    EXPECT_NEAR(r.max_offset_relative, r1.max_offset_relative, 1e-9) << s;
    for (std::size_t p = 0; p < mesh.points.size(); ++p)
      ASSERT_LT((mesh.points[p] / s - base.points[p]).norm(), 1e-12) << "scale " << s << ", point " << p;
  }
}

// A node the reference would pull through its flat tet stays straight.
TEST(Quadratic, EdgeThatWouldInvertStaysStraight) {
  TetMesh mesh{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.3, 0.3, 0.05)}, {{0, 1, 2, 3}}, {1}, {}, {}};
  ASSERT_GT(tet_volume(mesh, 0), 0);
  TriangleSoup reference;  // a triangle 0.2 above edge (0,1), far above the flat tet's apex
  reference.points = {Vec3(-1, -1, 0.2), Vec3(2, -1, 0.2), Vec3(0.5, -0.01, 0.2)};
  reference.triangles = {{0, 1, 2}};
  const QuadraticResult r = make_quadratic(mesh, &reference);
  EXPECT_GE(r.straight_inverting, 1u);
  EXPECT_EQ(r.nonpositive_jacobian_tets, 0u);
  const std::uint32_t node = mesh.tet_edge_nodes[0][0];  // edge (0,1)
  EXPECT_EQ(mesh.points[node], Vec3(0.5, 0, 0));
}

// The reference covers the cube's top only, a little above it: the top's edges move onto it, the
// sides' and the base's (whose nearest reference point is the top's) stay straight.
TEST(Quadratic, NodesFollowOnlyThePartOfTheBoundaryTheReferenceIsNear) {
  TetMesh mesh = test::cube_tets(2);
  TriangleSoup reference;
  reference.points = {Vec3(-0.5, -0.5, 1.01), Vec3(1.5, -0.5, 1.01), Vec3(1.5, 1.5, 1.01), Vec3(-0.5, 1.5, 1.01)};
  reference.triangles = {{0, 1, 2}, {0, 2, 3}};
  const std::size_t corners = mesh.points.size();
  const QuadraticResult r = make_quadratic(mesh, &reference);
  EXPECT_EQ(r.nonpositive_jacobian_tets, 0u);
  EXPECT_GT(r.straight_off_reference, 0u);
  for (std::size_t edge = 0; edge < r.edges; ++edge) {
    const Vec3& p = mesh.points[corners + edge];
    // Nodes moved are those of the top's edges (z = 1), to z = 1.01; no other moved.
    if (p.z() > 1.0) {
      EXPECT_DOUBLE_EQ(p.z(), 1.01);
    }
  }
  std::size_t top_edges = 0;
  for (std::size_t edge = 0; edge < r.edges; ++edge) top_edges += mesh.points[corners + edge].z() > 1.0;
  EXPECT_EQ(top_edges, r.curved_edges);
  EXPECT_EQ(r.curved_edges, 16u);  // the top of a 2 x 2 Kuhn cut: 12 lattice edges and 4 diagonals
}

TEST(Quadratic, BoundarySoupOfAFlatFaceIsTheFaceSubdivided) {
  TetMesh mesh = test::cube_tets(1);
  const TriangleSoup linear = quadratic_boundary(mesh, 3);
  EXPECT_EQ(linear.triangles.size(), 9u * 12u);
  make_quadratic(mesh);
  const TriangleSoup soup = quadratic_boundary(mesh, 3);
  EXPECT_EQ(soup.triangles.size(), 9u * 12u);
  // Outward, flat: the divergence theorem gives the cube's volume.
  double six_v = 0;
  for (const Triangle& t : soup.triangles) six_v += soup.points[t[0]].dot(soup.points[t[1]].cross(soup.points[t[2]]));
  EXPECT_NEAR(six_v / 6, 1.0, 1e-12);
  EXPECT_THROW(quadratic_boundary(mesh, 0), InvalidInput);
}

}  // namespace
}  // namespace meshprep
