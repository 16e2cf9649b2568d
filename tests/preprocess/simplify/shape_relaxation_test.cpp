// The relaxation on the original surface after the collapses (preprocess/src/reference_relaxation.h).
#include "simplify/reference_relaxation.h"
#include "shared/vertex_relaxation.h"

#include "meshprep/quality/triangle_bvh.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace meshprep {
namespace {

const double kTwentyDegrees = std::cos(20.0 * M_PI / 180.0);

TriMesh::VertexHandle vertex_at(const TriMesh& mesh, const Vec3& p) {
  for (const auto v : mesh.vertices())
    if ((to_eigen(mesh.point(v)) - p).norm() < 1e-12) return v;
  return TriMesh::VertexHandle();
}

double worst_ratio_around(const TriMesh& mesh, TriMesh::VertexHandle v) {
  return detail::worst_radius_ratio(mesh, v, to_eigen(mesh.point(v)));
}

TEST(ReferenceRelaxation, ATailVertexOfAPlaneEvensItsFacesAndStaysInThePlane) {
  const TriangleSoup plane = test::grid(6);
  const TriangleBvh reference(plane);
  TriMesh mesh = mesh_from_soup(plane);
  const auto v = vertex_at(mesh, Vec3(3, 3, 0));
  ASSERT_TRUE(v.is_valid());
  mesh.set_point(v, to_openmesh(Vec3(3.7, 3.6, 0)));  // its faces get radius ratios up to ~4
  const double before = worst_ratio_around(mesh, v);
  ASSERT_GT(before, 2.0);
  EXPECT_GE(detail::relax_on_reference(mesh, reference, 0.0, kTwentyDegrees, detail::HeightField{}), 1u);
  const Vec3 after = to_eigen(mesh.point(v));
  EXPECT_EQ(after.z(), 0.0);  // on the plane itself: its closest point, no offset
  EXPECT_LT(worst_ratio_around(mesh, v), before);
  EXPECT_LT((after - Vec3(3, 3, 0)).norm(), (Vec3(3.7, 3.6, 0) - Vec3(3, 3, 0)).norm());
}

TEST(ReferenceRelaxation, AVertexOnACreaseStays) {
  // The grid folded by 90 degrees along x = 3: the part beyond goes down the z axis.
  TriangleSoup folded = test::grid(6);
  for (Vec3& p : folded.points)
    if (p.x() > 3) p = Vec3(3, p.y(), -(p.x() - 3));
  const TriangleBvh reference(folded);
  TriMesh mesh = mesh_from_soup(folded);
  const auto v = vertex_at(mesh, Vec3(3, 3, 0));
  ASSERT_TRUE(v.is_valid());
  const Vec3 along_the_crease(3, 3.45, 0);
  mesh.set_point(v, to_openmesh(along_the_crease));
  ASSERT_GT(worst_ratio_around(mesh, v), 2.0);
  detail::relax_on_reference(mesh, reference, 0.0, kTwentyDegrees, detail::HeightField{});
  EXPECT_EQ(to_eigen(mesh.point(v)), along_the_crease);
}

}  // namespace
}  // namespace meshprep
