#include "repair/face_intersection.h"

#include <utility>

namespace meshprep::detail {
namespace {

// The chord of triangle t on the plane through `origin` with normal n: the points of t's closed
// boundary on the plane (vertices on it, and edges crossing it). None if t is on one side.
std::vector<ExactPoint> chord_on_plane(const ExactTriangle& t, const ExactPoint& n, const ExactPoint& origin) {
  std::array<Rational, 3> height;
  for (int i = 0; i < 3; ++i) height[i] = dot(n, minus(t[i], origin));
  std::vector<ExactPoint> chord;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (sgn(height[i]) == 0) chord.push_back(t[i]);
    if (sgn(height[i]) * sgn(height[j]) < 0) chord.push_back(along(t[i], t[j], height[i] / (height[i] - height[j])));
  }
  return chord;
}

// The extreme points of a chord along `direction`.
std::pair<ExactPoint, ExactPoint> ends_along(const std::vector<ExactPoint>& chord, const ExactPoint& direction,
                                             Rational& low, Rational& high) {
  std::pair<ExactPoint, ExactPoint> ends{chord[0], chord[0]};
  low = high = dot(direction, chord[0]);
  for (std::size_t i = 1; i < chord.size(); ++i) {
    const Rational s = dot(direction, chord[i]);
    if (s < low) low = s, ends.first = chord[i];
    if (s > high) high = s, ends.second = chord[i];
  }
  return ends;
}

// The 2-d orientation of p against the directed line u -> v, in the plane that drops `axis`.
Rational side(const ExactPoint& u, const ExactPoint& v, const ExactPoint& p, int axis) {
  const int x = (axis + 1) % 3, y = (axis + 2) % 3;
  return (v[x] - u[x]) * (p[y] - u[y]) - (v[y] - u[y]) * (p[x] - u[x]);
}

// b's edges clipped to the coplanar triangle a (Cyrus-Beck: each edge of a bounds the parameter
// of the segment on one side).
std::vector<CutSegment> edges_clipped_to(const ExactTriangle& a, const ExactTriangle& b, int axis) {
  const int orientation = sgn(side(a[0], a[1], a[2], axis));
  std::vector<CutSegment> cuts;
  for (int i = 0; i < 3; ++i) {
    const ExactPoint &p = b[i], &q = b[(i + 1) % 3];
    Rational low = 0, high = 1;
    bool empty = false;
    for (int k = 0; k < 3 && !empty; ++k) {
      // inside(t) = orientation * side(a_k, a_k+1, p + t (q - p)) >= 0, linear in t.
      const Rational at_p = orientation * side(a[k], a[(k + 1) % 3], p, axis);
      const Rational at_q = orientation * side(a[k], a[(k + 1) % 3], q, axis);
      if (at_p < 0 && at_q < 0) empty = true;
      else if (at_p < 0) low = std::max(low, Rational(at_p / (at_p - at_q)));
      else if (at_q < 0) high = std::min(high, Rational(at_p / (at_p - at_q)));
      empty = empty || low > high;
    }
    if (!empty) cuts.push_back({along(p, q, low), along(p, q, high)});
  }
  return cuts;
}

}  // namespace

FaceIntersection intersect_faces(const ExactTriangle& a, const ExactTriangle& b) {
  const ExactPoint na = normal(a), nb = normal(b);
  const ExactPoint direction = cross(na, nb);
  FaceIntersection result;
  if (sgn(direction[0]) == 0 && sgn(direction[1]) == 0 && sgn(direction[2]) == 0) {
    if (sgn(dot(na, minus(b[0], a[0]))) != 0) return result;  // parallel planes
    result.coplanar = true;
    const int axis = dominant_axis(na);
    result.in_a = edges_clipped_to(a, b, axis);
    result.in_b = edges_clipped_to(b, a, axis);
    return result;
  }
  const std::vector<ExactPoint> chord_a = chord_on_plane(a, nb, b[0]), chord_b = chord_on_plane(b, na, a[0]);
  if (chord_a.empty() || chord_b.empty()) return result;
  // Both chords lie on the planes' common line: their overlap is the faces' intersection.
  Rational low_a, high_a, low_b, high_b;
  const auto ends_a = ends_along(chord_a, direction, low_a, high_a);
  const auto ends_b = ends_along(chord_b, direction, low_b, high_b);
  if (low_a > high_b || low_b > high_a) return result;
  const CutSegment cut{low_a >= low_b ? ends_a.first : ends_b.first, high_a <= high_b ? ends_a.second : ends_b.second};
  result.in_a.push_back(cut);
  result.in_b.push_back(cut);
  return result;
}

}  // namespace meshprep::detail
