// The fast winding number (repair/winding_number.h) against the exact face-by-face sum, on
// closed, open and overlapping soups, in any unit.
#include "repair/winding_number.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace meshprep {
namespace {

double exact_winding_number(const TriangleSoup& soup, const Vec3& q) {
  double sum = 0;
  for (const Triangle& t : soup.triangles) sum += detail::winding_share(soup.points, t, q);
  return sum;
}

// Points of the cube [-2, 2]^3, uniformly at random (fixed seed).
std::vector<Vec3> sample_points(std::size_t count) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-2, 2);
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < count; ++i) points.emplace_back(coordinate(random), coordinate(random), coordinate(random));
  return points;
}

// A tenth of a turn: the number is read against one half between whole turns, which leaves 0.4.
// The series' error measured 0.03 a twentieth of a turn from the surface and 0.065 at the points
// nearest the sphere's faces here (the clusters next to the point are summed exactly).
constexpr double kTolerance = 0.1;

TEST(WindingNumber, AgreesWithTheExactSumOnAClosedSphere) {
  const TriangleSoup sphere = test::icosphere(4);  // 5,120 faces
  const detail::WindingNumber fast(sphere);
  std::size_t inside = 0;
  for (const Vec3& q : sample_points(400)) {
    if (std::abs(q.norm() - 1) < 0.02) continue;  // the faces' chord lies within 0.002 of the sphere
    const double exact = exact_winding_number(sphere, q);
    EXPECT_NEAR(fast.at(q), exact, kTolerance) << q.transpose();
    EXPECT_NEAR(exact, q.norm() < 1 ? 1.0 : 0.0, 1e-9);
    inside += q.norm() < 1;
  }
  EXPECT_GT(inside, 10u);  // both sides were asked
}

TEST(WindingNumber, OpenAndOverlappingSoupsAndAnyUnit) {
  // A sphere with its upper cap cut away (open), and a torus overlapping it (two closed parts
  // wrap the overlap twice): the number is 2 there, fractional near the hole.
  TriangleSoup open = test::icosphere(4);
  std::vector<Triangle> kept;
  for (const Triangle& t : open.triangles)
    if (open.points[t[0]].z() < 0.6 || open.points[t[1]].z() < 0.6 || open.points[t[2]].z() < 0.6) kept.push_back(t);
  open.triangles = kept;
  const TriangleSoup soup = test::merged(open, test::torus(48, 24, 1.2, 0.5));
  for (const double scale : {1e-3, 1.0, 1e3}) {
    TriangleSoup scaled = soup;
    for (Vec3& p : scaled.points) p *= scale;
    const detail::WindingNumber fast(scaled);
    for (const Vec3& q : sample_points(300))
      EXPECT_NEAR(fast.at(scale * q), exact_winding_number(scaled, scale * q), kTolerance) << scale << ": " << q.transpose();
  }
  const detail::WindingNumber fast(soup);
  // Read at one half: twice inside (less what the hole lets out) where the parts overlap, once in
  // the tube only, inside the open sphere below its hole, outside both.
  EXPECT_GT(fast.at(Vec3(0.8, 0, 0)), 1.5);
  EXPECT_NEAR(fast.at(Vec3(1.5, 0, 0)), 1, kTolerance);
  EXPECT_GT(fast.at(Vec3(0, 0, -0.5)), 0.5);
  EXPECT_LT(fast.at(Vec3(0, 0, 1.9)), 0.5);
}

TEST(WindingNumber, AnEmptySoupWrapsNothing) {
  const TriangleSoup empty;
  const detail::WindingNumber fast(empty);
  EXPECT_EQ(fast.at(Vec3::Zero()), 0);
}

}  // namespace
}  // namespace meshprep
