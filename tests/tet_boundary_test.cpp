// tet_boundary: the faces of one tet, outward, in tet order.
#include "meshprep/fem/tet_boundary.h"
#include "tet_test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace meshprep {
namespace {

// The same oriented triangle whatever corner it starts with.
Triangle rotated_to_smallest(const Triangle& f) {
  const auto k = static_cast<std::size_t>(std::min_element(f.begin(), f.end()) - f.begin());
  return {f[k], f[(k + 1) % 3], f[(k + 2) % 3]};
}

bool has_corners(const Tetrahedron& t, const Triangle& f) {
  return std::all_of(f.begin(), f.end(), [&](std::uint32_t v) { return std::count(t.begin(), t.end(), v) == 1; });
}

TEST(TetBoundary, CubeFacesOutwardInTetOrder) {
  const TetMesh mesh = test::cube_tets(2);
  const std::vector<Triangle> boundary = tet_boundary(mesh);
  std::map<Triangle, int> expected, found;  // oriented faces
  for (const Triangle& f : mesh.boundary_faces) ++expected[rotated_to_smallest(f)];
  for (const Triangle& f : boundary) ++found[rotated_to_smallest(f)];
  EXPECT_EQ(found, expected);
  std::size_t previous_tet = 0;
  for (const Triangle& f : boundary) {
    const auto owner = std::find_if(mesh.tets.begin(), mesh.tets.end(), [&](const Tetrahedron& t) { return has_corners(t, f); });
    ASSERT_NE(owner, mesh.tets.end());
    const auto t = static_cast<std::size_t>(owner - mesh.tets.begin());
    EXPECT_GE(t, previous_tet);
    previous_tet = t;
  }
}

// Three tets on the face 0 1 2: that face belongs to none's boundary; their 9 other faces do.
TEST(TetBoundary, FaceOfThreeTetsIsNotBoundary) {
  TetMesh mesh;
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {1, 1, 1}};
  mesh.tets = {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 5}};
  const std::vector<Triangle> boundary = tet_boundary(mesh);
  EXPECT_EQ(boundary.size(), 9u);
  for (Triangle f : boundary) {
    std::sort(f.begin(), f.end());
    EXPECT_NE(f, (Triangle{0, 1, 2})) << "the face of three tets";
  }
  EXPECT_TRUE(tet_boundary(TetMesh{}).empty());
}

// The single unit tet: each face points away from the opposite corner.
TEST(TetBoundary, SingleTetFacesPointAway) {
  TetMesh mesh;
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.tets = {{0, 1, 2, 3}};
  const std::vector<Triangle> boundary = tet_boundary(mesh);
  ASSERT_EQ(boundary.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    const Triangle& f = boundary[k];
    const Vec3 a = mesh.points[f[0]], b = mesh.points[f[1]], c = mesh.points[f[2]];
    EXPECT_LT((b - a).cross(c - a).dot(mesh.points[k] - a), 0) << "face " << k << " is opposite corner " << k;
  }
}

// The boundary as a surface: the faces of one tet each, their tags as patches with the names, on
// the points they use.
TEST(TetBoundary, TheBoundarySurfaceKeepsTheTagsAsNamedPatches) {
  TetMesh mesh = test::cube_tets(2);
  mesh.boundary_names = {{1, "x_min"}, {4, "Load"}};
  const TriangleSoup surface = boundary_surface(mesh);
  EXPECT_EQ(surface.triangles.size(), mesh.boundary_faces.size());
  EXPECT_LT(surface.points.size(), mesh.points.size());  // the cube's inner point is left out
  ASSERT_EQ(surface.patches.size(), surface.triangles.size());
  std::map<int, std::size_t> faces, expected;
  for (const int tag : surface.patches) ++faces[tag];
  for (const int tag : mesh.boundary_tags) ++expected[tag];
  EXPECT_EQ(faces, expected);
  EXPECT_EQ(surface.patch_names, mesh.boundary_names);
  double volume = 0;  // outward faces: the divergence theorem gives the cube's volume
  for (const Triangle& t : surface.triangles)
    volume += surface.points[t[0]].dot(surface.points[t[1]].cross(surface.points[t[2]])) / 6;
  EXPECT_NEAR(volume, 1.0, 1e-12);
  // All tag 1 without a name: nothing to keep.
  TetMesh plain = test::cube_tets(1);
  plain.boundary_tags.assign(plain.boundary_tags.size(), 1);
  EXPECT_TRUE(boundary_surface(plain).patches.empty());
}

}  // namespace
}  // namespace meshprep
