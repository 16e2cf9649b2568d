#include "meshprep/fem/knife_edges.h"

#include "improve/surface_limits.h"
#include "meshprep/quality/report.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/surface_distance.h"
#include "meshprep/quality/triangle_bvh.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace meshprep {
namespace {

using test::cube_with_cap;

double diagonal(const TriangleSoup& soup) { return bounding_box(soup).diagonal().norm(); }

TEST(KnifeEdges, ASurfaceWithoutOneIsLeftAsItIs) {
  const TriangleSoup sphere = test::icosphere(2);
  TriMesh mesh = mesh_from_soup(sphere);
  KnifeEdgeParams params;
  params.max_deviation = 2e-3 * diagonal(sphere);
  const KnifeEdgeResult r = open_knife_edges(mesh, sphere, params);
  EXPECT_EQ(r.knife_edges_before, 0u);
  EXPECT_TRUE(r.edits.empty());
  EXPECT_EQ(r.surface_bound_after_deg, params.goal_min_dihedral_deg);
  const TriangleSoup after = soup_from_mesh(mesh);
  EXPECT_EQ(after.points, sphere.points);
  EXPECT_EQ(after.triangles, sphere.triangles);
}

TEST(KnifeEdges, ACapIsFlippedAwayWithinTheBound) {
  const double bulge = 1e-4;
  const TriangleSoup input = cube_with_cap(bulge);
  ASSERT_EQ(find_self_intersections(input).count, 0u);
  TriMesh mesh = mesh_from_soup(input);
  KnifeEdgeParams params;
  params.max_deviation = 2e-3 * diagonal(input);
  const KnifeEdgeResult r = open_knife_edges(mesh, input, params);
  ASSERT_GE(r.knife_edges_before, 1u);
  EXPECT_LT(r.surface_bound_before_deg, 1.0);  // a cap of 180 - 0.016 degrees
  EXPECT_EQ(r.knife_edges_after, 0u);
  EXPECT_EQ(r.surface_bound_after_deg, params.goal_min_dihedral_deg);
  ASSERT_FALSE(r.edits.empty());
  EXPECT_STREQ(r.edits.front().kind, "cap");
  // The cap's vertex stays where it is: the surface moves by at most its distance from the cube.
  EXPECT_LE(r.max_displacement, bulge * (1 + 1e-9));
  EXPECT_GT(r.max_displacement, 0);
  const TriangleSoup after = soup_from_mesh(mesh);
  const QualityReport q = analyze_quality(after);
  EXPECT_TRUE(q.closed);
  EXPECT_TRUE(q.manifold);
  EXPECT_EQ(q.self_intersections, 0u);
  ASSERT_TRUE(q.volume.has_value());
  EXPECT_NEAR(*q.volume, 1.0, 1e-3);
}

TEST(KnifeEdges, NoEditMovesTheSurfaceFartherThanAllowed) {
  const double bulge = 1e-4;
  const TriangleSoup input = cube_with_cap(bulge);
  TriMesh mesh = mesh_from_soup(input);
  KnifeEdgeParams params;
  // Flipping the cap away moves the surface by the bulge; moving its vertex in by half of it
  // blunts it without opening it. So the cap stays, listed where it is.
  params.max_deviation = 0.5 * bulge;
  const KnifeEdgeResult r = open_knife_edges(mesh, input, params);
  for (const KnifeEdgePlace& e : r.edits) EXPECT_STRNE(e.edit, "flip");
  EXPECT_LE(r.max_displacement, params.max_deviation);
  ASSERT_EQ(r.left.size(), r.knife_edges_after);
  ASSERT_GE(r.left.size(), 1u);
  EXPECT_STREQ(r.left.front().kind, "cap");
  EXPECT_LT((r.left.front().place - Vec3(0.5, 0, 1)).norm(), 1e-3);  // the cap's centroid
  // Measured apart from the step's own figure: the surface lies within the bound of the input.
  EXPECT_LE(surface_distance(soup_from_mesh(mesh), input).hausdorff(), params.max_deviation * (1 + 1e-9));
}

TEST(KnifeEdges, TheWedgeBoundIsTheAngleOverThreeForAWideWedge) {
  // A right-angled edge, the solid the quadrant y < 0, z < 0 (faces (u, v, apex 0) with normal +z
  // and (v, u, apex 1) with normal +y): three tets of 30 degrees fit.
  const improve::BoundaryWedge right{{1, 0, 0}, {0, 0, 0}, {Vec3(0.5, -1, 0), Vec3(0.5, 0, -1)}};
  const double angle = improve::interior_angle_deg(right);
  EXPECT_NEAR(angle, 90, 1e-9);
  EXPECT_NEAR(improve::wedge_bound_deg(right, angle, 15), 30, 1e-9);
  // The same faces the other way round (normals -z and -y): the solid is the other three quadrants.
  const improve::BoundaryWedge reflex{{0, 0, 0}, {1, 0, 0}, {Vec3(0.5, -1, 0), Vec3(0.5, 0, -1)}};
  EXPECT_NEAR(improve::interior_angle_deg(reflex), 270, 1e-9);
}

}  // namespace
}  // namespace meshprep
