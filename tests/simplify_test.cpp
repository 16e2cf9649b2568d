#include "meshprep/core/errors.h"
#include "meshprep/preprocess/simplify.h"
#include "meshprep/quality/report.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

using namespace meshprep;

namespace {

QualityReport simplified_quality(const TriangleSoup& input, const SimplifyParams& params, SimplifyResult* result) {
  TriMesh mesh = mesh_from_soup(input);
  *result = simplify(mesh, params);
  QualityParams q;
  q.distance_samples = 20000;
  return analyze_quality(soup_from_mesh(mesh), q, &input);
}

}  // namespace

TEST(SimplifyQuadric, SphereStaysClosedGenus0NearTheSurface) {
  const TriangleSoup sphere = test::icosphere(4);  // 5120 faces
  SimplifyResult result;
  const QualityReport r = simplified_quality(sphere, {}, &result);
  EXPECT_EQ(result.target_faces, 512u);
  EXPECT_TRUE(result.reached_target);
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.manifold);
  EXPECT_EQ(*r.genus, 0);
  EXPECT_EQ(r.self_intersections, 0u);
  // Halfedge collapses keep every vertex on the unit sphere, so the distance is the sagitta of
  // the largest faces: 512 faces average ~0.16 edges, and quadric decimation leaves some ~0.5
  // long (sagitta 0.5^2 / 8 ~ 0.03). A stray vertex would be ~0.1 off or more.
  EXPECT_LT(r.reference->hausdorff, 0.05);
}

TEST(SimplifyQuadric, TorusKeepsGenus1) {
  SimplifyParams p;
  p.target_faces = 400;
  SimplifyResult result;
  const QualityReport r = simplified_quality(test::torus(48, 24), p, &result);
  EXPECT_TRUE(result.reached_target);
  EXPECT_EQ(*r.genus, 1);
  EXPECT_TRUE(r.manifold);
}

TEST(SimplifyQuadric, FlatGridCollapsesWithoutLeavingThePlane) {
  TriMesh mesh = mesh_from_soup(test::grid(20));  // 800 faces in z = 0
  SimplifyParams p;
  p.keep_ratio = 0.05;
  const SimplifyResult result = simplify(mesh, p);
  EXPECT_LE(result.faces_after, 40u);
  for (auto v : mesh.vertices()) EXPECT_EQ(mesh.point(v)[2], 0.0);  // halfedge collapses stay in the plane
  // OpenMesh's quadrics do not guard the border (the footprint may shrink): one loop remains.
  EXPECT_EQ(analyze_quality(soup_from_mesh(mesh)).boundary_loops, 1u);
}

TEST(SimplifyQuadric, BadParameters) {
  TriMesh mesh = mesh_from_soup(test::cube());
  SimplifyParams p;
  p.keep_ratio = 1.5;
  EXPECT_THROW(simplify(mesh, p), InvalidInput);
  TriMesh empty;
  EXPECT_THROW(simplify(empty, {}), InvalidInput);
}
