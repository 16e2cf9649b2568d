#pragma once
// Rational points for the self-intersection step (repair.h, step 6). Every input coordinate is a
// double, so it is a rational exactly; the points where faces cross and the points where the
// crossing segments cross are rationals of those, so the cut is computed without rounding and a
// point two faces share is the same point in both (GMP's mpq_class). Only the output is rounded.

#include "meshprep/core/mesh.h"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace meshprep::detail {

using Rational = mpq_class;
using ExactPoint = std::array<Rational, 3>;
using ExactTriangle = std::array<ExactPoint, 3>;

inline ExactPoint exact_point(const Vec3& p) { return {Rational(p.x()), Rational(p.y()), Rational(p.z())}; }

/// The nearest doubles towards zero (mpq_get_d): within one unit in the last place.
inline Vec3 rounded(const ExactPoint& p) { return {p[0].get_d(), p[1].get_d(), p[2].get_d()}; }

inline ExactPoint minus(const ExactPoint& a, const ExactPoint& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

inline ExactPoint cross(const ExactPoint& a, const ExactPoint& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline Rational dot(const ExactPoint& a, const ExactPoint& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// a + t (b - a).
inline ExactPoint along(const ExactPoint& a, const ExactPoint& b, const Rational& t) {
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

inline ExactPoint normal(const ExactTriangle& t) { return cross(minus(t[1], t[0]), minus(t[2], t[0])); }

/// The axis along which `n` is longest: dropping it projects the face's plane onto the other two
/// without folding it, and exactly (a projection only forgets a coordinate).
inline int dominant_axis(const ExactPoint& n) {
  const Rational x = abs(n[0]), y = abs(n[1]), z = abs(n[2]);
  return x >= y && x >= z ? 0 : (y >= z ? 1 : 2);
}

}  // namespace meshprep::detail
