// Orientation predicates in two stages (Shewchuk, "Adaptive Precision Floating-Point Arithmetic
// and Fast Robust Geometric Predicates", Discrete Comput. Geom. 18, 1997, section 4; the cases in
// the tests come from Kettner, Mehlhorn, Pion, Schirra and Yap, "Classroom examples of robustness
// problems in geometric computations", Comput. Geom. 40, 2008):
//  1. a filter: the determinant in doubles with an a-priori bound on its rounding error; when the
//     determinant is larger than the bound its sign is right, and it is returned as it is. The
//     expressions and bounds are Shewchuk's error bounds A, evaluated in the same order, so the
//     value returned is bit for bit the one TetGen's predicates.cxx returns (the report's figures
//     do not move).
//  2. otherwise, the exact determinant in integers: every double is an integer times a power of
//     two, so all coordinates of a call scale to integers by one common power of two, and the
//     differences, products and sums are exact in GMP's mpz. Where Shewchuk refines in stages of
//     floating-point expansions, this stage is one plain evaluation: ~2.5 us a call against ~40 ns
//     for the filter and ~1.3 us for Shewchuk's adaptive stages on the same near-coplanar inputs
//     (one run, 2-core VM), reached on a small share of the calls (coplanar CAD faces, needles).
// The filter assumes no product underflows (differences below ~1e-100 in orient3d), as Shewchuk's;
// the exact stage has no such limit. Compiled with -ffp-contract=off (CMakeLists.txt): a fused
// multiply-add would change the filter's values, and its error bound would need a new proof.

#include "robust_predicates.h"

#include <gmp.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>

namespace meshprep::detail {
namespace {

// The unit roundoff of doubles (round to nearest): |fl(x op y) - x op y| <= eps |fl(x op y)|.
constexpr double kEps = 0x1p-53;

// orient3d: det = adz (bdx cdy - cdx bdy) + bdz (cdx ady - adx cdy) + cdz (adx bdy - bdx ady), with
// the nine differences rounded. Along the path of each term the roundings are: the two differences
// of a product and the product (3), the difference of two products (1), the third difference and
// the product with it (2): each term is within (6 eps + O(eps^2)) |adz| (|bdx cdy| + |cdx bdy|) of
// its exact value, all measured on the computed quantities. The first of the two sums adds one
// rounding (7 eps); the last one cannot change the sign (rounding to nearest is monotone and keeps
// zero), so it costs nothing. Hence |det - exact| <= 7 eps permanent + O(eps^2) permanent, with
// permanent = sum of |z-difference| (|product| + |product|) as below. The 56 eps^2 covers the
// second-order terms and the two roundings of errbound itself (Shewchuk's bound A, his eq. for
// o3derrboundA; TetGen's exactinit computes the same double).
constexpr double kOrient3dBound = (7.0 + 56.0 * kEps) * kEps;

// orient2d: det = (ax - cx)(by - cy) - (ay - cy)(bx - cx): three roundings on each product's path
// (two differences, the product), the final difference free as above: 3 eps (|left| + |right|);
// 16 eps^2 for the rest (Shewchuk's ccwerrboundA).
constexpr double kOrient2dBound = (3.0 + 16.0 * kEps) * kEps;

// Reusable mpz integers for one thread: after the first calls the exact stage allocates nothing.
struct Integers {
  static constexpr int kCount = 32;
  mpz_t z[kCount];
  Integers() {
    for (auto& v : z) mpz_init2(v, 256);
  }
  ~Integers() {
    for (auto& v : z) mpz_clear(v);
  }
  Integers(const Integers&) = delete;
  Integers& operator=(const Integers&) = delete;
};

Integers& integers() {
  thread_local Integers scratch;
  return scratch;
}

// Sets out[i] = x[i] / 2^scale, an exact integer, for the returned scale: the exponent of the
// lowest significand bit among the x[i] (frexp: x = f 2^e with f in [0.5, 1), so f 2^53 is an
// integer below 2^53, also for subnormals).
int scale_to_integers(const double* x, int n, mpz_t* out) {
  std::int64_t significand[12];
  int exponent[12];
  int scale = INT_MAX;
  for (int i = 0; i < n; ++i) {
    int e = 0;
    significand[i] = static_cast<std::int64_t>(std::ldexp(std::frexp(x[i], &e), 53));
    exponent[i] = e - 53;
    if (significand[i] != 0) scale = std::min(scale, exponent[i]);
  }
  if (scale == INT_MAX) scale = 0;
  for (int i = 0; i < n; ++i) {
    mpz_set_si(out[i], static_cast<long>(significand[i]));
    if (significand[i] != 0) mpz_mul_2exp(out[i], out[i], static_cast<mp_bitcnt_t>(exponent[i] - scale));
  }
  return scale;
}

// value 2^scale as a double of the same sign: truncated, and the smallest subnormal rather than
// zero when it is too small for a double.
double to_double(const mpz_t value, long scale) {
  const int sign = mpz_sgn(value);
  if (sign == 0) return 0.0;
  long exponent = 0;
  const double significand = mpz_get_d_2exp(&exponent, value);
  const double result = std::ldexp(significand, static_cast<int>(exponent + scale));
  return result != 0 ? result : sign * std::numeric_limits<double>::denorm_min();
}

}  // namespace

double orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  mpz_t* z = integers().z;
  const double x[12] = {a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), c.x(), c.y(), c.z(), d.x(), d.y(), d.z()};
  const long scale = scale_to_integers(x, 12, z);
  mpz_t *ad = z + 12, *bd = z + 15, *cd = z + 18, &t = z[21], &u = z[22], &det = z[23];
  for (int k = 0; k < 3; ++k) {
    mpz_sub(ad[k], z[k], z[9 + k]);
    mpz_sub(bd[k], z[3 + k], z[9 + k]);
    mpz_sub(cd[k], z[6 + k], z[9 + k]);
  }
  mpz_set_ui(det, 0);
  // det = adz (bdx cdy - cdx bdy) + bdz (cdx ady - adx cdy) + cdz (adx bdy - bdx ady)
  const mpz_t* rows[3][3] = {{&ad[2], &bd[0], &cd[1]}, {&bd[2], &cd[0], &ad[1]}, {&cd[2], &ad[0], &bd[1]}};
  const mpz_t* cols[3][2] = {{&cd[0], &bd[1]}, {&ad[0], &cd[1]}, {&bd[0], &ad[1]}};
  for (int k = 0; k < 3; ++k) {
    mpz_mul(t, *rows[k][1], *rows[k][2]);
    mpz_mul(u, *cols[k][0], *cols[k][1]);
    mpz_sub(t, t, u);
    mpz_addmul(det, t, *rows[k][0]);
  }
  return to_double(det, 3 * scale);
}

double orient2d_exact(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  mpz_t* z = integers().z;
  const double x[6] = {a.x(), a.y(), b.x(), b.y(), c.x(), c.y()};
  const long scale = scale_to_integers(x, 6, z);
  mpz_t &acx = z[6], &acy = z[7], &bcx = z[8], &bcy = z[9], &det = z[10], &right = z[11];
  mpz_sub(acx, z[0], z[4]);
  mpz_sub(acy, z[1], z[5]);
  mpz_sub(bcx, z[2], z[4]);
  mpz_sub(bcy, z[3], z[5]);
  mpz_mul(det, acx, bcy);
  mpz_mul(right, acy, bcx);
  mpz_sub(det, det, right);
  return to_double(det, 2 * scale);
}

double orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double adx = a.x() - d.x(), ady = a.y() - d.y(), adz = a.z() - d.z();
  const double bdx = b.x() - d.x(), bdy = b.y() - d.y(), bdz = b.z() - d.z();
  const double cdx = c.x() - d.x(), cdy = c.y() - d.y(), cdz = c.z() - d.z();
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * std::abs(adz) +
                           (std::abs(cdxady) + std::abs(adxcdy)) * std::abs(bdz) +
                           (std::abs(adxbdy) + std::abs(bdxady)) * std::abs(cdz);
  const double errbound = kOrient3dBound * permanent;
  if (det > errbound || -det > errbound) return det;
  return orient3d_exact(a, b, c, d);
}

double orient2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const double left = (a.x() - c.x()) * (b.y() - c.y());
  const double right = (a.y() - c.y()) * (b.x() - c.x());
  const double det = left - right;
  // Products of opposite signs (or a zero one) cannot cancel: the sign of det is theirs, exact,
  // since a rounded difference or product is zero only when the exact one is (barring underflow).
  double sum = 0;
  if (left > 0) {
    if (right <= 0) return det;
    sum = left + right;
  } else if (left < 0) {
    if (right >= 0) return det;
    sum = -left - right;
  } else {
    return det;
  }
  const double errbound = kOrient2dBound * sum;
  if (det >= errbound || -det >= errbound) return det;
  return orient2d_exact(a, b, c);
}

}  // namespace meshprep::detail
