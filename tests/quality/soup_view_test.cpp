// Measuring a halfedge mesh through MeshSoupView (soup_view.h) must give, bit for bit, what
// measuring soup_from_mesh(mesh) gives: the same faces in the same order, the same numbering.
#include "meshprep/core/soup_view.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/surface_distance.h"
#include "meshprep/quality/triangle_bvh.h"
#include "meshprep/quality/triangle_metrics.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

using namespace meshprep;
using namespace meshprep::test;

namespace {

// Two icospheres that cross each other: faces of every shape and some self-intersections.
TriMesh crossing_spheres() {
  return mesh_from_soup(merged(icosphere(2), translated(icosphere(2, 0.8), Vec3(1.1, 0.2, 0.1))));
}

// What a view sees, copied into a soup of its own.
TriangleSoup to_soup(const SoupView& surface) {
  TriangleSoup soup;
  for (std::size_t v = 0; v < surface.points.size(); ++v) soup.points.push_back(surface.points[v]);
  soup.triangles.assign(surface.triangles.begin(), surface.triangles.end());
  return soup;
}

void expect_same_soup(const TriangleSoup& a, const TriangleSoup& b) {
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t v = 0; v < a.points.size(); ++v) EXPECT_EQ(a.points[v], b.points[v]) << "vertex " << v;
  EXPECT_EQ(a.triangles, b.triangles);
}

// Every measure the stages take on a mesh, compared exactly (EXPECT_EQ on doubles: the same
// operations on the same doubles in the same order).
void expect_same_measures(const TriMesh& mesh) {
  const TriangleSoup soup = soup_from_mesh(mesh);
  const MeshSoupView surface(mesh);
  expect_same_soup(to_soup(surface), soup);

  const std::vector<TriangleShape> from_soup = triangle_shapes(soup), from_mesh = triangle_shapes(surface);
  ASSERT_EQ(from_soup.size(), from_mesh.size());
  for (std::size_t f = 0; f < from_soup.size(); ++f) {
    EXPECT_EQ(from_soup[f].radius_ratio, from_mesh[f].radius_ratio) << "face " << f;
    EXPECT_EQ(from_soup[f].min_angle_deg, from_mesh[f].min_angle_deg) << "face " << f;
    EXPECT_EQ(from_soup[f].area, from_mesh[f].area) << "face " << f;
  }
  EXPECT_EQ(signed_volume(soup), signed_volume(surface));
  EXPECT_EQ(bbox_diagonal(soup), bbox_diagonal(surface));

  const SelfIntersections a = find_self_intersections(soup), b = find_self_intersections(surface);
  EXPECT_GT(a.count, 0u);  // the spheres cross: the pairs are compared, not two empty lists
  EXPECT_EQ(a.pairs, b.pairs);
  EXPECT_EQ(a.exact_tests, b.exact_tests);

  const TriangleBvh bvh_soup(soup), bvh_mesh(surface);
  for (const Vec3& p : {Vec3(0.3, 0.2, 2.0), Vec3(-1.5, 0.1, 0.4), Vec3(1.0, 0.0, 0.0)}) {
    const TriangleBvh::Hit x = bvh_soup.closest_point(p), y = bvh_mesh.closest_point(p);
    EXPECT_EQ(x.face, y.face);
    EXPECT_EQ(x.squared_distance, y.squared_distance);
  }
}

}  // namespace

TEST(MeshSoupView, MeasuresAsItsSoup) { expect_same_measures(crossing_spheres()); }

TEST(MeshSoupView, SkipsDeletedFacesBeforeGarbageCollection) {
  TriMesh mesh = crossing_spheres();
  // Faces deleted, their vertices kept (still used by other faces): the points are borrowed and
  // the deleted faces skipped, as soup_from_mesh skips them.
  for (const int f : {0, 7, 100}) mesh.delete_face(TriMesh::FaceHandle(f), false);
  expect_same_measures(mesh);
}

TEST(MeshSoupView, RenumbersAroundDeletedVertices) {
  TriMesh mesh = crossing_spheres();
  // A vertex deleted with its faces (not yet collected): the numbering closes up as the soup's.
  mesh.delete_vertex(TriMesh::VertexHandle(3), false);
  mesh.delete_vertex(TriMesh::VertexHandle(50), false);
  ASSERT_LT(soup_from_mesh(mesh).points.size(), mesh.n_vertices());
  expect_same_measures(mesh);
}

TEST(MeshSoupView, SeesTheMeshPointsWithoutCopyingThem) {
  TriMesh mesh = crossing_spheres();
  const MeshSoupView surface(mesh);
  const SoupView view = surface;
  mesh.set_point(TriMesh::VertexHandle(5), TriMesh::Point(9, 8, 7));
  EXPECT_EQ(view.points[5], Vec3(9, 8, 7));  // borrowed: the moved point is seen
}

TEST(SoupView, ViewsASoupImplicitly) {
  const TriangleSoup soup = icosphere(1);
  const SoupView view = soup;
  ASSERT_EQ(view.points.size(), soup.points.size());
  ASSERT_EQ(view.triangles.size(), soup.triangles.size());
  EXPECT_EQ(view.points[7], soup.points[7]);
  EXPECT_EQ(view.triangles.data(), soup.triangles.data());  // seen, not copied
  expect_same_soup(to_soup(view), soup);
}
