// The closed triangle-triangle test on the configurations that decide exactness: coplanar,
// parallel, touching, sharing an edge, crossing; each in many rigid placements. Touching cases only
// move by exact motions (the cube's 24 rotations, translations by powers of two, on coordinates that
// are small multiples of 1/4): a rounded motion may legitimately part or merge what only touches.
// Cases whose answer holds with a margin (or whose contact is a shared corner, which any motion
// moves identically) also move by random rotations and translations.
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/triangle_intersection.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <string>
#include <vector>

using namespace meshprep;

namespace {

using Corners = std::array<Vec3, 3>;

struct Motion {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Vec3 translation = Vec3::Zero();
  Corners operator()(const Corners& t) const {
    return {rotation * t[0] + translation, rotation * t[1] + translation, rotation * t[2] + translation};
  }
};

// The 24 rotations of the cube (signed permutation matrices of determinant +1), each with a
// translation by powers of two: exact on the cases' coordinates.
std::vector<Motion> exact_motions() {
  const std::array<std::array<int, 3>, 6> permutations{{{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};
  const std::array<Vec3, 4> translations{Vec3(0, 0, 0), Vec3(1, -2, 4), Vec3(-0.125, 64, -0.5), Vec3(1048576, 0.25, -32768)};
  std::vector<Motion> motions;
  for (const auto& permutation : permutations)
    for (int signs = 0; signs < 8; ++signs) {
      Motion m;
      m.rotation.setZero();
      for (int row = 0; row < 3; ++row) m.rotation(row, permutation[row]) = (signs >> row & 1) ? -1 : 1;
      if (m.rotation.determinant() < 0) continue;
      m.translation = translations[motions.size() % translations.size()];
      motions.push_back(m);
    }
  return motions;
}

// Rotations uniform over SO(3) (normalised Gaussian quaternions) and translations up to 100 edges.
std::vector<Motion> random_motions(int count) {
  std::mt19937_64 random(20260312);
  std::normal_distribution<double> gaussian;
  std::uniform_real_distribution<double> offset(-100, 100);
  std::vector<Motion> motions(count);
  for (Motion& m : motions) {
    m.rotation = Eigen::Quaterniond(gaussian(random), gaussian(random), gaussian(random), gaussian(random))
                     .normalized()
                     .toRotationMatrix();
    m.translation = Vec3(offset(random), offset(random), offset(random));
  }
  return motions;
}

struct Case {
  std::string name;
  Corners a, b;
  bool intersect;
  bool answer_survives_rounding;  // may move by random (rounded) motions
};

const Corners kBase{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0)};

std::vector<Case> cases() {
  return {
      {"coplanar, overlapping", kBase, {Vec3(0.5, 0.5, 0), Vec3(3, 0.5, 0), Vec3(0.5, 3, 0)}, true, false},
      {"coplanar, half an edge apart", kBase, {Vec3(3, 0, 0), Vec3(5, 0, 0), Vec3(3, 2, 0)}, false, true},
      {"coplanar, corner on an edge", kBase, {Vec3(1, 1, 0), Vec3(3, 1, 0), Vec3(3, 3, 0)}, true, false},
      {"coplanar, sharing an edge (a flat quad)", kBase, {Vec3(2, 0, 0), Vec3(2, 2, 0), Vec3(0, 2, 0)}, true, true},
      {"coplanar, sharing a corner", kBase, {Vec3(2, 0, 0), Vec3(4, 0, 0), Vec3(4, -2, 0)}, true, true},
      {"parallel, half an edge above", kBase, {Vec3(0, 0, 1), Vec3(2, 0, 1), Vec3(0, 2, 1)}, false, true},
      {"parallel, above and shifted by half an edge", kBase, {Vec3(1, 0, 1), Vec3(3, 0, 1), Vec3(1, 2, 1)}, false, true},
      {"corner touching the inside", kBase, {Vec3(0.5, 0.5, 0), Vec3(0.5, 0.5, 2), Vec3(1.5, -1, 1)}, true, false},
      {"corner touching a corner", kBase, {Vec3(2, 0, 0), Vec3(3, 0, 1), Vec3(3, 1, 1)}, true, true},
      {"sharing an edge, hinged", kBase, {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, -1, 1.5)}, true, true},
      {"sharing an edge, leaning over the other", kBase, {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0.5, 1.5)}, true, true},
      {"edge lying on the other's face", kBase, {Vec3(0.5, 0.25, 0), Vec3(0.25, 0.5, 0), Vec3(1, 1, 2)}, true, false},
      {"crossing", kBase, {Vec3(0.5, 0.5, -1), Vec3(0.5, 0.5, 1), Vec3(1.5, -1, 0.5)}, true, true},
      {"crossing each other's edges", kBase, {Vec3(-1, 0.5, -1), Vec3(3, 0.5, -1), Vec3(1, 0.5, 1)}, true, true},
      {"separated, a quarter edge above", kBase, {Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.5, 2), Vec3(1.5, -1, 1)}, false, true},
      {"separated, pointing at an edge", kBase, {Vec3(1.5, 1.5, 0), Vec3(2, 2, -1), Vec3(2, 2, 1)}, false, true},
  };
}

// The test is symmetric and does not depend on where each triangle's corners start or turn.
void expect_answer(const Corners& a, const Corners& b, bool intersect, const std::string& where) {
  for (int shift = 0; shift < 3; ++shift)
    for (bool reverse : {false, true}) {
      Corners b2;
      for (int i = 0; i < 3; ++i) b2[i] = b[(shift + (reverse ? 3 - i : i)) % 3];
      EXPECT_EQ(triangles_intersect(a[0], a[1], a[2], b2[0], b2[1], b2[2]), intersect) << where;
      EXPECT_EQ(triangles_intersect(b2[0], b2[1], b2[2], a[0], a[1], a[2]), intersect) << where << ", swapped";
    }
}

TEST(TriangleIntersection, ExactUnderExactRigidMotions) {
  const std::vector<Motion> motions = exact_motions();
  ASSERT_EQ(motions.size(), 24u);
  for (const Case& c : cases())
    for (std::size_t m = 0; m < motions.size(); ++m)
      expect_answer(motions[m](c.a), motions[m](c.b), c.intersect, c.name + ", rotation " + std::to_string(m));
}

TEST(TriangleIntersection, ExactUnderRandomRigidMotions) {
  for (const Case& c : cases())
    if (c.answer_survives_rounding)
      for (const Motion& motion : random_motions(200)) expect_answer(motion(c.a), motion(c.b), c.intersect, c.name);
}

// The case: two triangles of one (tilted, rounded) plane, half an edge apart. Their corners
// lie off each other's plane by rounding alone, so both planes cross both triangles almost
// parallel to each other; the old test compared the crossings along a direction computed from the
// two nearly equal normals (rounding noise) and called about 1 pair in 130 intersecting.
TEST(TriangleIntersection, TrianglesOfOneTiltedPlaneHalfAnEdgeApart) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 origin(coordinate(random), coordinate(random), coordinate(random));
    const Vec3 u(coordinate(random), coordinate(random), coordinate(random));
    const Vec3 v(coordinate(random), coordinate(random), coordinate(random));
    auto at = [&](double s, double t) -> Vec3 { return origin + s * u + t * v; };
    EXPECT_FALSE(triangles_intersect(at(0, 0), at(1, 0), at(0, 1), at(1.5, 0), at(2.5, 0), at(1.5, 1))) << i;
  }
  // One such pair (i = 301, whose boxes overlap), as two faces of a mesh: no self-intersection.
  TriangleSoup soup;
  soup.points = {{0.52669318948901611, 0.38016040612745172, -0.047170457949650135},
                 {0.3952549322088722, 1.1018707877044083, 0.18883234092835766},
                 {-0.45153344509307258, -0.058046646589939632, -0.31007161653541293},
                 {0.32953580356880025, 1.4627259784928865, 0.30683374036736155},
                 {0.19809754628865633, 2.1844363600698431, 0.54283653924536934},
                 {-0.64869083101328839, 1.0245189257754952, 0.043932581781598756}};
  soup.triangles = {{0, 1, 2}, {3, 4, 5}};
  EXPECT_EQ(find_self_intersections(soup).count, 0u);
}

TEST(TriangleIntersection, CollinearCornersHaveNoArea) {
  EXPECT_TRUE(triangle_has_area({0, 0, 0}, {1, 0, 0}, {0, 1e-300, 0}));
  EXPECT_FALSE(triangle_has_area({0.1, 0.2, 0.3}, {0.2, 0.4, 0.6}, {0.4, 0.8, 1.2}));
  EXPECT_FALSE(triangle_has_area({1, 1, 1}, {1, 1, 1}, {2, 3, 4}));
}

TEST(TriangleIntersection, SegmentThroughTriangle) {
  EXPECT_TRUE(segment_intersects_triangle({0.2, 0.2, -1}, {0.2, 0.2, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  EXPECT_FALSE(segment_intersects_triangle({0.8, 0.8, -1}, {0.8, 0.8, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  EXPECT_FALSE(segment_intersects_triangle({0.2, 0.2, 0.1}, {0.2, 0.2, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  // In the triangle's plane: through it, along an edge, beside it.
  EXPECT_TRUE(segment_intersects_triangle({-1, 0.25, 0}, {2, 0.25, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  EXPECT_TRUE(segment_intersects_triangle({-1, 0, 0}, {0.5, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  EXPECT_FALSE(segment_intersects_triangle({1, 1, 0}, {2, 0.5, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
}

}  // namespace
