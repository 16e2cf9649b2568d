// The adaptive reconstruction: the reconstruction on a finer grid, simplified back.
#include "meshprep/preprocess/compose/adaptive_reconstruction.h"
#include "meshprep/quality/report.h"
#include "preprocess/scattered_points.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace meshprep;
using meshprep::test::sample;

TEST(AdaptiveReconstruction, MeshIsDenserWhereTheSurfaceBends) {
  // A sharp bump in the middle of a flat square: --adaptive keeps about the uniform grid's face
  // count but puts more of its vertices on the bump, and is closer to the true surface there.
  auto bump = [](double x, double y) { return 0.3 * std::exp(-30 * (x * x + y * y)); };
  const std::vector<Vec3> points = sample(3000, bump);
  ReconstructParams params;
  params.columns = params.rows = 40;
  const ReconstructResult uniform = reconstruct_surface(points, params);
  const ReconstructResult adaptive = reconstruct_adaptive(points, {params, {}});
  const QualityReport q = analyze_quality(adaptive.mesh);
  EXPECT_TRUE(q.manifold);
  EXPECT_EQ(q.self_intersections, 0u);
  EXPECT_NEAR(static_cast<double>(adaptive.mesh.triangles.size()), static_cast<double>(uniform.mesh.triangles.size()),
              0.05 * static_cast<double>(uniform.mesh.triangles.size()));
  auto on_bump = [](const TriangleSoup& mesh) {
    std::size_t count = 0;
    for (const Vec3& p : mesh.points) count += p.head<2>().norm() < 0.4;
    return static_cast<double>(count) / static_cast<double>(mesh.points.size());
  };
  EXPECT_GT(on_bump(adaptive.mesh), 1.5 * on_bump(uniform.mesh));
  EXPECT_EQ(adaptive.vertex_variation.size(), adaptive.mesh.points.size());
}
