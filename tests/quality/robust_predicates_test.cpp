// quality's orientation predicates against an exact reference written independently (GMP's
// rationals, the cofactor expansion of the 3 x 3 determinant): on the near-degenerate inputs where
// the plain double determinant gets the sign wrong (so the filter cannot have decided them and the
// exact stage answers), on inputs whose coordinates span the whole exponent range, and on exactly
// degenerate ones. Cases after Kettner, Mehlhorn, Pion, Schirra and Yap, "Classroom examples of
// robustness problems in geometric computations" (Comput. Geom. 40, 2008), section 3.
#include "robust_predicates.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace meshprep;
using Vec2 = Eigen::Vector2d;

namespace {

int sign_of(double v) { return (v > 0) - (v < 0); }

int exact_orient2d_sign(const Vec2& a, const Vec2& b, const Vec2& c) {
  const mpq_class det = (mpq_class(a.x()) - c.x()) * (mpq_class(b.y()) - c.y()) -
                        (mpq_class(a.y()) - c.y()) * (mpq_class(b.x()) - c.x());
  return sgn(det);
}

int exact_orient3d_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  mpq_class m[3][3];
  const Vec3* rows[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) m[i][k] = mpq_class((*rows[i])[k]) - mpq_class(d[k]);
  const mpq_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                        m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                        m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return sgn(det);
}

// The filter's own floating-point determinants, without the filter.
double naive_orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (a.x() - c.x()) * (b.y() - c.y()) - (a.y() - c.y()) * (b.x() - c.x());
}

double naive_orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 ad = a - d, bd = b - d, cd = c - d;
  return ad.z() * (bd.x() * cd.y() - cd.x() * bd.y()) + bd.z() * (cd.x() * ad.y() - ad.x() * cd.y()) +
         cd.z() * (ad.x() * bd.y() - bd.x() * ad.y());
}

// x moved by `ulps` units in its last place.
double ulps_away(double x, int ulps) {
  for (; ulps > 0; --ulps) x = std::nextafter(x, HUGE_VAL);
  for (; ulps < 0; ++ulps) x = std::nextafter(x, -HUGE_VAL);
  return x;
}

}  // namespace

// Kettner et al.'s Figure 1: p = (0.5 + i u, 0.5 + j u), u = 2^-53, against the line through
// q = (12, 12) and r = (24, 24). In doubles the signs of the 256 x 256 grid come out scattered.
TEST(RobustPredicates, Orient2dIsExactOnKettnersGrid) {
  const Vec2 q(12, 12), r(24, 24);
  int naive_wrong = 0;
  for (int i = 0; i < 256; ++i)
    for (int j = 0; j < 256; ++j) {
      const Vec2 p(0.5 + i * 0x1p-53, 0.5 + j * 0x1p-53);
      const int expected = exact_orient2d_sign(p, q, r);
      naive_wrong += sign_of(naive_orient2d(p, q, r)) != expected;
      ASSERT_EQ(sign_of(detail::orient2d(p, q, r)), expected) << i << ", " << j;
      ASSERT_EQ(sign_of(detail::orient2d_exact(p, q, r)), expected) << i << ", " << j;
      ASSERT_EQ(sign_of(detail::orient2d(q, r, p)), expected) << i << ", " << j;  // cyclic: same sign
    }
  EXPECT_GT(naive_wrong, 0) << "the grid no longer fools plain doubles: it tests nothing";
}

// A point of the plane of a, b, c, rounded to doubles, then moved by a few ulps along each axis.
TEST(RobustPredicates, Orient3dIsExactNextToAPlane) {
  const Vec3 a(0.1, 0.2, 0.3), b(1.7, -0.3, 2.9), c(-2.3, 3.1, 0.7);
  const Vec3 on_plane = a + 0.37 * (b - a) + 0.41 * (c - a);
  int naive_wrong = 0, zeros = 0;
  for (int i = -6; i <= 6; ++i)
    for (int j = -6; j <= 6; ++j)
      for (int k = -6; k <= 6; ++k) {
        const Vec3 d(ulps_away(on_plane.x(), i), ulps_away(on_plane.y(), j), ulps_away(on_plane.z(), k));
        const int expected = exact_orient3d_sign(a, b, c, d);
        naive_wrong += sign_of(naive_orient3d(a, b, c, d)) != expected;
        zeros += expected == 0;
        ASSERT_EQ(sign_of(detail::orient3d(a, b, c, d)), expected) << i << ", " << j << ", " << k;
        ASSERT_EQ(sign_of(detail::orient3d_exact(a, b, c, d)), expected) << i << ", " << j << ", " << k;
        ASSERT_EQ(sign_of(detail::orient3d(b, c, a, d)), expected) << i << ", " << j << ", " << k;
      }
  EXPECT_GT(naive_wrong, 0) << "no case fools plain doubles: the exact stage is not tested";
  RecordProperty("exactly_coplanar", zeros);
}

// Exactly coplanar and collinear points give exactly zero, whatever their magnitude and offset.
TEST(RobustPredicates, DegenerateIsExactlyZero) {
  const double offsets[] = {0.0, 1e-300, 0.1, 1e15, -3e200};
  for (double o : offsets) {
    const Vec3 a(o, o, o), b(o + 1, o, o), c(o, o + 1, o), d(o + 3, o + 0.25, o);  // all in z = o
    EXPECT_EQ(detail::orient3d(a, b, c, d), 0.0) << o;
    const Vec2 p(o, o), q(o + 0.5, o + 0.5), r(o + 1, o + 1);  // all on y = x
    EXPECT_EQ(detail::orient2d(p, q, r), 0.0) << o;
  }
  const Vec3 x(1, 2, 3);
  EXPECT_EQ(detail::orient3d(x, x, Vec3(4, 5, 6), Vec3(7, 8, 10)), 0.0);
  EXPECT_EQ(detail::orient3d_exact(x, x, Vec3(4, 5, 6), Vec3(7, 8, 10)), 0.0);
}

// Coordinates from 2^-1074 to 1e300 in one call: the exact stage scales them to one integer grid,
// and a determinant too small for a double keeps its sign.
TEST(RobustPredicates, ExactStageSpansTheExponentRange) {
  const double tiny = 0x1p-1074, small = 1e-300, big = 1e300;
  const Vec3 a(0, 0, 0), b(big, 0, 0), c(0, big, 0);
  for (double z : {tiny, -tiny, small, -small}) {
    const Vec3 d(1, 1, z);
    const int expected = exact_orient3d_sign(a, b, c, d);
    ASSERT_NE(expected, 0);
    EXPECT_EQ(sign_of(detail::orient3d_exact(a, b, c, d)), expected) << z;
    EXPECT_EQ(sign_of(detail::orient3d(a, b, c, d)), expected) << z;
  }
  const Vec3 p(tiny, 0, 0), q(0, tiny, 0), r(0, 0, tiny);
  EXPECT_EQ(sign_of(detail::orient3d_exact(p, q, r, Vec3::Zero())), exact_orient3d_sign(p, q, r, Vec3::Zero()));
  EXPECT_NE(detail::orient3d_exact(p, q, r, Vec3::Zero()), 0.0);  // 2^-3222: no double, but a sign
  const Vec2 u(tiny, 0), v(0, tiny);
  EXPECT_EQ(sign_of(detail::orient2d_exact(u, v, Vec2::Zero())), exact_orient2d_sign(u, v, Vec2::Zero()));
}

// Random points on a plane z = x/4 + y/2 (exact for most of them) and off it, at any scale: the
// signs agree with the reference, and where the filter decides, the value is the plain determinant
// (the report's magnitudes depend on it).
TEST(RobustPredicates, RandomNearCoplanarAgreesWithReference) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::uniform_int_distribution<int> exponent(-60, 60), ulps(-2, 2);
  for (int n = 0; n < 20000; ++n) {
    const double scale = std::ldexp(1.0, exponent(rng));
    Vec3 p[4];
    for (Vec3& v : p) {
      const double x = uniform(rng) * scale, y = uniform(rng) * scale;
      v = Vec3(x, y, ulps_away(0.25 * x + 0.5 * y, n % 3 == 0 ? ulps(rng) : 0));
    }
    const int expected = exact_orient3d_sign(p[0], p[1], p[2], p[3]);
    const double value = detail::orient3d(p[0], p[1], p[2], p[3]);
    ASSERT_EQ(sign_of(value), expected) << n;
    const double naive = naive_orient3d(p[0], p[1], p[2], p[3]);
    if (value != naive) {
      ASSERT_EQ(value, detail::orient3d_exact(p[0], p[1], p[2], p[3])) << n;
    }
  }
}
