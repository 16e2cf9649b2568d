// The enhancement's remeshing (adaptive_remeshing.h, sizing_field.h) on the tessellations a CAD
// export makes: needles across a plane, strips around a cylinder, a thin slab of two triangles a
// side. Issue 32's tests.
#include "meshprep/preprocess/enhance/enhance.h"

#include "meshprep/core/io.h"
#include "meshprep/core/mesh.h"
#include "meshprep/core/soup_view.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/surface_distance.h"
#include "meshprep/quality/triangle_bvh.h"
#include "meshprep/quality/triangle_metrics.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace meshprep;
using namespace meshprep::test;

namespace {

struct Shape {
  double under_20 = 0;  // share of faces with a smallest angle under 20 degrees
  double radius_ratio_p95 = 0;
};

Shape shape_of(const TriangleSoup& soup) {
  std::vector<double> ratios;
  std::size_t under = 0;
  for (const TriangleShape& s : triangle_shapes(soup)) {
    ratios.push_back(s.radius_ratio);
    under += s.min_angle_deg < 20;
  }
  std::sort(ratios.begin(), ratios.end());
  return {static_cast<double>(under) / static_cast<double>(ratios.size()), ratios[ratios.size() * 95 / 100]};
}

std::vector<double> edge_lengths(const TriMesh& mesh) {
  std::vector<double> lengths;
  for (const auto e : mesh.edges()) lengths.push_back(mesh.calc_edge_length(e));
  std::sort(lengths.begin(), lengths.end());
  return lengths;
}

// A 20 x 1 rectangle in the plane z = 0 whose long bottom side has 20 vertices and whose top side
// has only its corners: a fan of needles from the top-left corner, as a CAD exporter writes a face.
TriangleSoup needle_rectangle() {
  TriangleSoup s;
  constexpr int n = 20;
  for (int i = 0; i <= n; ++i) s.points.emplace_back(20.0 * i / n, 0.0, 0.0);
  const auto top_left = static_cast<std::uint32_t>(s.points.size());
  s.points.emplace_back(0.0, 1.0, 0.0);
  s.points.emplace_back(20.0, 1.0, 0.0);
  for (std::uint32_t i = 0; i < n; ++i) s.triangles.push_back({top_left, i, i + 1});
  s.triangles.push_back({top_left, n, top_left + 1});
  return s;
}

// A closed box of 12 triangles, `thickness` thick and `side` wide.
TriangleSoup slab(double side, double thickness) {
  TriangleSoup s = cube(1.0);
  for (Vec3& p : s.points) p = Vec3(p.x() * side, p.y() * side, p.z() * thickness);
  return s;
}

// The cube [0, side]^3 with its edge from (side, side, 0) to (side, side, side) chamfered `cut`
// along both faces: a strip of two triangles whose short ends are edges between two corners.
TriangleSoup chamfered_cube(double side, double cut) {
  TriangleSoup s;
  const auto point = [&s](double x, double y, double z) {
    s.points.emplace_back(x, y, z);
    return static_cast<std::uint32_t>(s.points.size() - 1);
  };
  const double a = side, b = side - cut;
  const std::uint32_t o = point(0, 0, 0), x = point(a, 0, 0), y = point(0, a, 0), z = point(0, 0, a), zx = point(a, 0, a),
                      yz = point(0, a, a), p1 = point(b, a, 0), p2 = point(a, b, 0), p3 = point(b, a, a), p4 = point(a, b, a);
  // Each face as a polygon fanned from its first corner, oriented along its outward normal.
  const auto face = [&s](const std::vector<std::uint32_t>& polygon, const Vec3& outward) {
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
      Triangle t{polygon[0], polygon[i], polygon[i + 1]};
      const Vec3 n = (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]);
      if (n.dot(outward) < 0) std::swap(t[1], t[2]);
      s.triangles.push_back(t);
    }
  };
  face({o, x, zx, z}, -Vec3::UnitY());
  face({o, z, yz, y}, -Vec3::UnitX());
  face({o, y, p1, p2, x}, -Vec3::UnitZ());
  face({z, zx, p4, p3, yz}, Vec3::UnitZ());
  face({x, p2, p4, zx}, Vec3::UnitX());
  face({y, yz, p3, p1}, Vec3::UnitY());
  face({p1, p3, p4, p2}, Vec3(1, 1, 0));
  return s;
}

}  // namespace

// A CAD part's short edge between two corners stays; the faces around it grade up from its length
// by the grading (1.5) instead of jumping to the part's size next to it, which would leave the
// tets there no room for the goal.
TEST(Remesh, FacesGradeUpFromAShortEdgeBetweenCorners) {
  const double side = 10, cut = 0.2;
  TriMesh mesh = mesh_from_soup(chamfered_cube(side, cut));
  const EnhanceResult result = enhance(mesh, nullptr, [] {
    EnhanceParams p;
    p.remesh = EnhanceRemesh::On;
    return p;
  }());
  ASSERT_TRUE(result.remeshed);
  const double chamfer = cut * std::sqrt(2.0);
  const Vec3 end(side - cut / 2, side - cut / 2, 0);  // the middle of the strip's end at z = 0
  // An edge within distance d of the end asks for at most chamfer + 0.5 (d + its own length); the
  // remeshing splits above 4/3 of the field. Without the grading the edges there reach the part's
  // size (several units).
  std::size_t near = 0;
  for (const auto e : mesh.edges()) {
    const Vec3 middle = to_eigen(mesh.calc_edge_midpoint(e));
    const double d = (middle - end).norm();
    if (d > 1.0) continue;
    ++near;
    const double length = mesh.calc_edge_length(e);
    EXPECT_LE(length, 4.0 / 3.0 * (chamfer + 0.5 * (d + length))) << "at " << middle.transpose();
  }
  EXPECT_GE(near, 10u);
  ASSERT_TRUE(result.size_field);
  EXPECT_LE((*result.size_field)(end), chamfer * (1 + 1e-9));
}

// The scanned hand's fingers pass closer than the remeshing's faces: its first remeshing crosses
// itself. Run again, finer where it crossed, it does not, and is kept; before, it was taken back
// and the input's own faces, enhanced, ended 3.0e-3 of the diagonal from the input, over the bound.
TEST(Remesh, ARemeshingThatCrossedItselfIsRunAgainFinerWhereItCrossed) {
  const LoadedMesh hand = load_mesh(MESHPREP_TEST_DATA_DIR "/hand.off");
  ASSERT_EQ(find_self_intersections(hand.soup).count, 0u);
  TriMesh mesh = hand.mesh;
  const EnhanceResult result = enhance(mesh, nullptr, [] {
    EnhanceParams p;
    p.time_limit_seconds = 0;  // the remeshings run to their end on a slow (sanitizer) build too
    return p;
  }());
  ASSERT_TRUE(result.remeshed);
  EXPECT_EQ(result.remesh_crossing_refinements, 1u);
  EXPECT_EQ(find_self_intersections(MeshSoupView(mesh)).count, 0u);
  const double diagonal = bbox_diagonal(hand.soup);
  EXPECT_LE(surface_distance(soup_from_mesh(mesh), hand.soup).hausdorff(), result.max_deviation * diagonal);
  // Finer only around the crossings: the field's faces stay within a few times the input's.
  EXPECT_LT(result.faces_after, 4 * result.faces_before);
}

TEST(Remesh, NeedlesAcrossAPlaneBecomeWellShapedInThePlane) {
  const TriangleSoup input = needle_rectangle();
  ASSERT_GT(shape_of(input).under_20, 0.9);
  TriMesh mesh = mesh_from_soup(input);
  const EnhanceResult result = enhance(mesh, nullptr);
  EXPECT_TRUE(result.remeshed);
  EXPECT_GT(result.faces_after, result.faces_before);
  // The remeshing's own time is part of the whole.
  EXPECT_GT(result.remesh_seconds, 0.0);
  EXPECT_LE(result.remesh_seconds, result.seconds);
  const TriangleSoup output = soup_from_mesh(mesh);
  const Shape shape = shape_of(output);
  EXPECT_LE(shape.under_20, 0.01);
  EXPECT_LE(shape.radius_ratio_p95, 2.0);
  // Exactly in the plane, and exactly on the rectangle's sides where on its border.
  double area = 0;
  for (const auto f : mesh.faces()) area += mesh.calc_face_area(f);
  EXPECT_NEAR(area, 20.0, 1e-9);
  for (const auto v : mesh.vertices()) {
    const Vec3 p = to_eigen(mesh.point(v));
    EXPECT_EQ(p.z(), 0.0);
    if (mesh.is_boundary(v)) {
      EXPECT_TRUE(p.x() == 0 || p.x() == 20 || p.y() == 0 || p.y() == 1) << p.transpose();
    }
  }
  for (const Vec3& corner : {Vec3(0, 0, 0), Vec3(20, 0, 0), Vec3(0, 1, 0), Vec3(20, 1, 0)}) {
    bool kept = false;
    for (const auto v : mesh.vertices()) kept = kept || to_eigen(mesh.point(v)) == corner;
    EXPECT_TRUE(kept) << "corner " << corner.transpose();
  }
}

TEST(Remesh, CylinderStripsBecomeNearEquilateralWithinTheBound) {
  // 48 strips 1 tall and 0.13 wide (smallest angle 7.5 degrees), caps fanned from one corner.
  const TriangleSoup input = cylinder_with_fan_caps(48);
  TriMesh mesh = mesh_from_soup(input);
  const EnhanceResult result = enhance(mesh, nullptr);
  EXPECT_TRUE(result.remeshed);
  const TriangleSoup output = soup_from_mesh(mesh);
  const Shape shape = shape_of(output);
  EXPECT_LE(shape.under_20, 0.01);
  EXPECT_LE(shape.radius_ratio_p95, 2.0);
  const double diagonal = bounding_box(input).diagonal().norm();
  DistanceParams sampling;
  sampling.samples = 100000;
  EXPECT_LE(surface_distance(output, input, sampling).hausdorff(), result.max_deviation * diagonal);
  EXPECT_NEAR(signed_volume(output), signed_volume(input), 1e-3 * signed_volume(input));
}

TEST(Remesh, AThinSlabGetsEdgesAboutItsThickness) {
  const double thickness = 0.25;
  TriMesh mesh = mesh_from_soup(slab(4.0, thickness));
  const EnhanceResult result = enhance(mesh, nullptr, [] {
    EnhanceParams p;
    p.remesh = EnhanceRemesh::On;  // two right triangles a side: nothing under 20 degrees
    return p;
  }());
  EXPECT_TRUE(result.remeshed);
  const std::vector<double> lengths = edge_lengths(mesh);
  // The thickness is sampled no farther apart than it is, so a point of the slab is at most
  // t / sqrt(3) along the faces from the nearest sample's centroid, and t / 2 across them (the
  // middle of a side): the target is at most t (1 + 1/2 sqrt(1/3 + 1/4)) (the field grows by half
  // the distance); edges are split above 4/3 of it.
  EXPECT_LE(lengths[lengths.size() / 2], 1.1 * thickness);
  EXPECT_LE(lengths.back(), 4.0 / 3.0 * (1 + 0.5 * std::sqrt(1.0 / 3.0 + 1.0 / 4.0)) * thickness);
  // The slab's eight corners stay.
  std::size_t corners = 0;
  for (const auto v : mesh.vertices()) {
    const Vec3 p = to_eigen(mesh.point(v));
    corners += (p.x() == 0 || p.x() == 4) && (p.y() == 0 || p.y() == 4) && (p.z() == 0 || p.z() == thickness);
  }
  EXPECT_EQ(corners, 8u);
}

TEST(Remesh, TheSameFiguresScaledAndRotated) {
  const TriangleSoup input = cylinder_with_fan_caps(48);
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  TriangleSoup turned = input;
  for (Vec3& p : turned.points) p = 1e-3 * (rotation * p) + Vec3(5e-3, -2e-3, 1e-3);
  TriMesh a = mesh_from_soup(input), b = mesh_from_soup(turned);
  const EnhanceResult ra = enhance(a, nullptr), rb = enhance(b, nullptr);
  // The bound is relative to the bounding box's diagonal, which the rotation changes (by 9 %
  // here), and the axis-aligned cylinder's ties (rays through edges, equal flips) go other ways:
  // both meet the goals, and the face counts agree; the radius ratio's p95 does not (1.56
  // against 1.16 when this was written).
  EXPECT_NEAR(static_cast<double>(rb.faces_after), static_cast<double>(ra.faces_after), 0.15 * static_cast<double>(ra.faces_after));
  const Shape sa = shape_of(soup_from_mesh(a)), sb = shape_of(soup_from_mesh(b));
  EXPECT_LE(sa.under_20, 0.01);
  EXPECT_LE(sb.under_20, 0.01);
  EXPECT_LE(sa.radius_ratio_p95, 2.0);
  EXPECT_LE(sb.radius_ratio_p95, 2.0);
  DistanceParams sampling;
  sampling.samples = 100000;
  EXPECT_LE(surface_distance(soup_from_mesh(b), turned, sampling).hausdorff(), rb.max_deviation * bounding_box(turned).diagonal().norm());
}
