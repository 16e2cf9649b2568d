// The Fig. 6 combination: simplify in three steps, each followed by enhance against the input.
#include "meshprep/core/errors.h"
#include "meshprep/preprocess/compose/simplify_and_enhance.h"
#include "meshprep/quality/report.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <vector>

using namespace meshprep;

TEST(SimplifyAndEnhance, ReachesTheTargetInThreeEnhancedSteps) {
  const TriangleSoup sphere = test::icosphere(4);
  TriMesh mesh = mesh_from_soup(sphere);
  SimplifyAndEnhanceParams params;
  params.simplify.keep_ratio = 0.2;
  std::vector<double> reported;
  params.progress = [&reported](double fraction) { reported.push_back(fraction); };
  const SimplifyAndEnhanceResult result = simplify_and_enhance(mesh, params);
  EXPECT_EQ(result.stages, 3u);
  EXPECT_TRUE(result.simplify.reached_target);
  EXPECT_EQ(result.simplify.faces_before, sphere.triangles.size());
  EXPECT_EQ(result.simplify.faces_after, mesh.n_faces());
  EXPECT_GT(result.simplify.collapses, 0u);
  ASSERT_FALSE(reported.empty());
  EXPECT_EQ(reported.back(), 1.0);
  const QualityReport q = analyze_quality(soup_from_mesh(mesh));
  EXPECT_TRUE(q.closed);
  EXPECT_EQ(q.self_intersections, 0u);
}

TEST(SimplifyAndEnhance, TheQuadricBaselineReducesOnceWithoutEnhancing) {
  TriMesh mesh = mesh_from_soup(test::icosphere(3));
  SimplifyAndEnhanceParams params;
  params.simplify.keep_ratio = 0.5;
  params.simplify.cost = CollapseCost::Quadric;
  const SimplifyAndEnhanceResult result = simplify_and_enhance(mesh, params);
  EXPECT_EQ(result.stages, 0u);
  EXPECT_TRUE(result.simplify.reached_target);
}

TEST(SimplifyAndEnhance, RefusesTheParametersSimplifyRefuses) {
  TriMesh mesh = mesh_from_soup(test::icosphere(2));
  SimplifyAndEnhanceParams params;
  params.simplify.keep_ratio = 1.5;
  EXPECT_THROW(simplify_and_enhance(mesh, params), InvalidInput);
  params.simplify.keep_ratio = 0.5;
  params.simplify.min_angle_deg = 70;
  EXPECT_THROW(simplify_and_enhance(mesh, params), InvalidInput);
}
