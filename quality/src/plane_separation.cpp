#include "plane_separation.h"

namespace meshprep::detail {
namespace {

// The orientation det(b - a, c - a, p - a) for the corners p of `other`, each evaluated in doubles
// as n . (p - a) with n = (b - a) x (c - a). Every rounding (the three differences, the products,
// the sums) is relative to the terms it touches, so the error is below a small multiple of
// eps = 2^-53 times the permanent sum_k |p_k - a_k| (|u_i v_j| + |u_j v_i|) (u = b - a, v = c - a;
// the same forward analysis as Shewchuk's orient3d error bound, "Adaptive Precision Floating-Point
// Arithmetic and Fast Robust Geometric Predicates", 1997, about 8 eps here); 2^-48 = 32 eps
// leaves room. Below 2^-900 an underflow could cost more than the bound, so nothing is certified.
bool strictly_on_one_side(const std::array<Vec3, 3>& t, const std::array<Vec3, 3>& other) {
  const Vec3 u = t[1] - t[0], v = t[2] - t[0];
  const Vec3 n = u.cross(v);
  const Vec3 n_bound(std::abs(u.y() * v.z()) + std::abs(u.z() * v.y()), std::abs(u.z() * v.x()) + std::abs(u.x() * v.z()),
                     std::abs(u.x() * v.y()) + std::abs(u.y() * v.x()));
  int side = 0;
  for (const Vec3& p : other) {
    const Vec3 w = p - t[0];
    const double value = n.dot(w), permanent = n_bound.dot(w.cwiseAbs());
    if (!(permanent > 0x1p-900) || !(std::abs(value) > 0x1p-48 * permanent)) return false;
    const int s = value > 0 ? 1 : -1;
    if (side != 0 && s != side) return false;
    side = s;
  }
  return true;
}

}  // namespace

bool certainly_separated_by_a_plane(const std::array<Vec3, 3>& t, const std::array<Vec3, 3>& u) {
  return strictly_on_one_side(t, u) || strictly_on_one_side(u, t);
}

}  // namespace meshprep::detail
