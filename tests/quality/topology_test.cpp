#include "meshprep/quality/coincident_vertices.h"
#include "meshprep/quality/face_edges.h"
#include "meshprep/quality/topology.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace meshprep;

TEST(Topology, RegularTetrahedronIsClosedGenus0) {
  const Topology t = analyze_topology(test::regular_tetrahedron());
  EXPECT_TRUE(t.closed);
  EXPECT_TRUE(t.manifold);
  EXPECT_TRUE(t.oriented);
  EXPECT_EQ(t.edges, 6u);
  EXPECT_EQ(t.euler_characteristic, 2);
  ASSERT_TRUE(t.genus.has_value());
  EXPECT_EQ(*t.genus, 0);
  EXPECT_EQ(t.components, 1u);
}

TEST(Topology, CubeIsClosedGenus0) {
  const Topology t = analyze_topology(test::cube());
  EXPECT_TRUE(t.closed);
  EXPECT_TRUE(t.oriented);
  EXPECT_EQ(t.euler_characteristic, 2);  // 8 - 18 + 12
  EXPECT_EQ(*t.genus, 0);
}

TEST(Topology, TorusHasGenus1) {
  const Topology t = analyze_topology(test::torus(24, 12));
  EXPECT_TRUE(t.closed);
  EXPECT_TRUE(t.manifold);
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_EQ(*t.genus, 1);
}

TEST(Topology, TwoComponentsAddUp) {
  const Topology t = analyze_topology(test::merged(test::cube(), test::translated(test::torus(16, 8), {10, 0, 0})));
  EXPECT_EQ(t.components, 2u);
  EXPECT_EQ(t.euler_characteristic, 2);  // 2 + 0
  EXPECT_EQ(*t.genus, 1);                // (2*2 - 2) / 2
}

TEST(Topology, HoleGivesBorderEdgesAndOneLoop) {
  TriangleSoup s = test::icosphere(2);
  s.triangles.erase(s.triangles.begin());  // remove one face: a triangular hole
  const Topology t = analyze_topology(s);
  EXPECT_FALSE(t.closed);
  EXPECT_EQ(t.border_edges, 3u);
  EXPECT_EQ(t.boundary_loops, 1u);
  EXPECT_TRUE(t.manifold);
  EXPECT_FALSE(t.genus.has_value());
  EXPECT_EQ(t.euler_characteristic, 1);  // a disc
}

TEST(Topology, GridHasOneBoundaryLoop) {
  const Topology t = analyze_topology(test::grid(5));
  EXPECT_EQ(t.border_edges, 20u);
  EXPECT_EQ(t.boundary_loops, 1u);
  EXPECT_EQ(t.euler_characteristic, 1);
}

TEST(Topology, BowTieVertexIsNonManifold) {
  TriangleSoup s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  s.triangles = {{0, 1, 2}, {0, 3, 4}};  // two triangles touching only at vertex 0
  const Topology t = analyze_topology(s);
  EXPECT_EQ(t.non_manifold_vertices, 1u);
  EXPECT_EQ(t.non_manifold_edges, 0u);
  EXPECT_FALSE(t.manifold);
  EXPECT_EQ(t.components, 2u);
}

TEST(Topology, FinEdgeIsNonManifold) {
  TriangleSoup s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  s.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};  // three faces on edge 0-1
  const Topology t = analyze_topology(s);
  EXPECT_EQ(t.non_manifold_edges, 1u);
  EXPECT_EQ(t.non_manifold_edge_faces.size(), 3u);
  EXPECT_FALSE(t.manifold);
}

TEST(Topology, FlippedFaceIsNotOriented) {
  TriangleSoup s = test::cube();
  std::swap(s.triangles[0][1], s.triangles[0][2]);
  const Topology t = analyze_topology(s);
  EXPECT_TRUE(t.closed);
  EXPECT_TRUE(t.manifold);
  EXPECT_FALSE(t.oriented);
  EXPECT_EQ(t.inconsistent_edges, 3u);
}

TEST(Topology, DuplicateAndRepeatedIndexFaces) {
  TriangleSoup s = test::cube();
  s.triangles.push_back({2, 1, 0});  // same vertex set as face 0
  s.triangles.push_back({0, 0, 1});  // repeats a vertex
  const Topology t = analyze_topology(s);
  EXPECT_EQ(t.duplicate_faces, 1u);
  ASSERT_EQ(t.duplicate_face_indices.size(), 1u);
  EXPECT_EQ(t.duplicate_face_indices[0], 12u);
  EXPECT_EQ(t.repeated_index_faces, 1u);
  EXPECT_FALSE(t.manifold);
}

TEST(Topology, IsolatedVerticesAreNotCounted) {
  TriangleSoup s = test::regular_tetrahedron();
  s.points.emplace_back(5, 5, 5);
  const Topology t = analyze_topology(s);
  EXPECT_EQ(t.isolated_vertices, 1u);
  EXPECT_EQ(t.referenced_vertices, 4u);
  EXPECT_EQ(t.euler_characteristic, 2);
}

// A seam of split vertices is found and welded; two closed bodies touching at corners are not a seam.
TEST(CoincidentVertices, SplitSeamsAreFoundTouchingBodiesAreNot) {
  const TriangleSoup cube = test::cube();
  TriangleSoup split;
  for (const Triangle& t : cube.triangles) {
    const auto first = static_cast<std::uint32_t>(split.points.size());
    for (const std::uint32_t v : t) split.points.push_back(cube.points[v]);
    split.triangles.push_back({first, first + 1, first + 2});
  }
  const CoincidentVertices found = find_coincident_vertices(split);
  EXPECT_EQ(found.merged, 3 * cube.triangles.size() - cube.points.size());
  EXPECT_EQ(found.faces.size(), cube.triangles.size());
  const Topology welded = analyze_topology(found.welded);
  EXPECT_TRUE(welded.closed);
  EXPECT_TRUE(welded.manifold);

  EXPECT_EQ(find_coincident_vertices(cube).merged, 0u);
  const TriangleSoup touching = test::merged(cube, test::translated(cube, {1, 0, 0}));  // share a face's corners
  EXPECT_EQ(find_coincident_vertices(touching).merged, 0u);
  EXPECT_TRUE(find_coincident_vertices(touching).welded.triangles.empty());
}

TEST(FaceEdges, SortedByEdgeThenFaceWhateverTheIndices) {
  // The counting sort sizes its runs by the faces' own indices: faces naming vertices past the
  // points (none given) or in any order still give every edge of every proper face, sorted by
  // (edge, face), and no edge of a face that repeats a vertex.
  TriangleSoup soup;
  soup.triangles = {{7, 2, 5}, {5, 2, 9}, {3, 3, 1}, {9, 2, 0}};
  const std::vector<FaceEdge> edges = sorted_face_edges(soup);
  ASSERT_EQ(edges.size(), 9u);
  for (std::size_t i = 1; i < edges.size(); ++i) {
    const FaceEdge &x = edges[i - 1], &y = edges[i];
    EXPECT_TRUE(x.key < y.key || (x.key == y.key && x.face < y.face));
  }
  EXPECT_EQ(std::count_if(edges.begin(), edges.end(), [](const FaceEdge& e) { return e.key == edge_key(2, 5); }), 2);
  EXPECT_EQ(std::count_if(edges.begin(), edges.end(), [](const FaceEdge& e) { return e.face == 2; }), 0);
}
