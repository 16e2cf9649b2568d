#include "repair/cut_face.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace meshprep::detail {
namespace {

using Edge = std::pair<int, int>;

Edge edge(int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; }

// The face's points in its plane, projected by dropping its normal's dominant axis.
class PlanePoints {
 public:
  explicit PlanePoints(int dropped_axis) : x_((dropped_axis + 1) % 3), y_((dropped_axis + 2) % 3) {}

  int add(const ExactPoint& p) {
    const auto [it, added] = index_.emplace(p, static_cast<int>(points_.size()));
    if (added) {
      points_.push_back(p);
      approx_.push_back({p[x_].get_d(), p[y_].get_d()});
    }
    return it->second;
  }
  int size() const { return static_cast<int>(points_.size()); }
  const ExactPoint& operator[](int i) const { return points_[i]; }
  std::vector<ExactPoint> release() { return std::move(points_); }

  // The sign of the orientation of (i, j, k). The doubles nearest the coordinates are each within
  // 2^-52 M of them (M the largest), so the differences u, v are within 2^-51 M and the determinant
  // within about 1.4e-15 M S of the exact one, S = |ux| + |uy| + |vx| + |vy| (the products'
  // rounding included): beyond 1e-13 M S its sign is certain; nearer, the integers decide.
  int orientation(int i, int j, int k) const {
    const auto &a = approx_[i], &b = approx_[j], &c = approx_[k];
    const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
    const double det = ux * vy - uy * vx;
    double largest = 0;
    for (const auto* p : {&a, &b, &c}) largest = std::max({largest, std::abs((*p)[0]), std::abs((*p)[1])});
    if (std::abs(det) > 1e-13 * largest * (std::abs(ux) + std::abs(uy) + std::abs(vx) + std::abs(vy)))
      return det > 0 ? 1 : -1;
    return exact_orientation(points_[i], points_[j], points_[k]);
  }

  // The sign of (q - p)_x (r - p)_y - (q - p)_y (r - p)_x over integers: each difference of two
  // fractions kept as numerator and denominator (positive), the two products compared by cross
  // multiplication. No fraction is reduced, so no gcd is taken: mpq's reductions were three
  // quarters of the time on a rotated part, whose nearly collinear cuts often need this.
  int exact_orientation(const ExactPoint& p, const ExactPoint& q, const ExactPoint& r) const {
    const auto difference = [](const Rational& a, const Rational& b, mpz_class& numerator, mpz_class& denominator) {
      numerator = a.get_num() * b.get_den() - b.get_num() * a.get_den();
      denominator = a.get_den() * b.get_den();
    };
    mpz_class n1, d1, n2, d2, n3, d3, n4, d4;
    difference(q[x_], p[x_], n1, d1);
    difference(r[y_], p[y_], n2, d2);
    difference(q[y_], p[y_], n3, d3);
    difference(r[x_], p[x_], n4, d4);
    return sgn(mpz_class(n1 * n2 * d3 * d4 - n3 * n4 * d1 * d2));
  }

  // Does point p lie on the open segment (i, j)?
  bool inside_segment(int p, int i, int j) const {
    if (p == i || p == j || orientation(i, j, p) != 0) return false;
    const ExactPoint &a = points_[i], &b = points_[j], &c = points_[p];
    const Rational along = (c[x_] - a[x_]) * (b[x_] - a[x_]) + (c[y_] - a[y_]) * (b[y_] - a[y_]);
    const Rational length = (b[x_] - a[x_]) * (b[x_] - a[x_]) + (b[y_] - a[y_]) * (b[y_] - a[y_]);
    return sgn(along) > 0 && along < length;
  }

  // Do the segments cross at a point inside both (not at an end of either)?
  bool cross_properly(const Edge& s, const Edge& t) const {
    if (s.first == t.first || s.first == t.second || s.second == t.first || s.second == t.second) return false;
    return orientation(s.first, s.second, t.first) * orientation(s.first, s.second, t.second) < 0 &&
           orientation(t.first, t.second, s.first) * orientation(t.first, t.second, s.second) < 0;
  }

  // The point where two properly crossing segments cross, on the face's plane: both are on it, so
  // the point along s at the crossing parameter is the exact 3-d point.
  ExactPoint crossing(const Edge& s, const Edge& t) const {
    const ExactPoint &p = points_[s.first], &q = points_[s.second], &r = points_[t.first], &w = points_[t.second];
    const auto cross2 = [this](const ExactPoint& u0, const ExactPoint& u1, const ExactPoint& v0, const ExactPoint& v1) {
      return Rational((u1[x_] - u0[x_]) * (v1[y_] - v0[y_]) - (u1[y_] - u0[y_]) * (v1[x_] - v0[x_]));
    };
    return along(p, q, cross2(p, r, r, w) / cross2(p, q, r, w));
  }

  double squared_length(int i, int j) const {
    const double dx = approx_[i][0] - approx_[j][0], dy = approx_[i][1] - approx_[j][1];
    return dx * dx + dy * dy;
  }

 private:
  int x_, y_;
  std::vector<ExactPoint> points_;
  std::vector<std::array<double, 2>> approx_;
  std::map<ExactPoint, int> index_;
};

// Splits the segments where a point lies inside one or two cross, until none does: afterwards
// the segments meet only at their ends. Each pass finds one such event and restarts.
std::vector<Edge> split_where_they_meet(PlanePoints& points, std::set<Edge> segments) {
  const auto split = [&segments](const Edge& old, int p) {
    segments.erase(old);
    segments.insert(edge(old.first, p));
    segments.insert(edge(p, old.second));
  };
  const auto split_one = [&]() {
    for (const Edge& s : segments)
      for (int p = 0; p < points.size(); ++p)
        if (points.inside_segment(p, s.first, s.second)) {
          split(Edge(s), p);
          return true;
        }
    for (auto s = segments.begin(); s != segments.end(); ++s)
      for (auto t = std::next(s); t != segments.end(); ++t)
        if (points.cross_properly(*s, *t)) {
          const Edge a = *s, b = *t;
          const int p = points.add(points.crossing(a, b));
          split(a, p);
          split(b, p);
          return true;
        }
    return false;
  };
  while (split_one()) {
  }
  return {segments.begin(), segments.end()};
}

}  // namespace

CutFace cut_face(const ExactTriangle& face, const std::vector<CutSegment>& cuts,
                 const std::vector<ExactPoint>& boundary_points) {
  PlanePoints points(dominant_axis(normal(face)));
  for (const ExactPoint& corner : face) points.add(corner);
  std::set<Edge> constraints{edge(0, 1), edge(1, 2), edge(0, 2)};
  for (const CutSegment& cut : cuts) {
    const int a = points.add(cut.from), b = points.add(cut.to);
    if (a != b) constraints.insert(edge(a, b));
  }
  for (const ExactPoint& p : boundary_points) points.add(p);
  std::vector<Edge> edges = split_where_they_meet(points, constraints);

  // Greedy: every other pair of points, shortest first, kept if it crosses nothing kept.
  const int n = points.size();
  std::vector<std::set<int>> neighbours(n);
  for (const Edge& e : edges) neighbours[e.first].insert(e.second), neighbours[e.second].insert(e.first);
  std::vector<Edge> candidates;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (!neighbours[i].count(j)) candidates.push_back({i, j});
  std::sort(candidates.begin(), candidates.end(), [&](const Edge& a, const Edge& b) {
    return points.squared_length(a.first, a.second) < points.squared_length(b.first, b.second);
  });
  for (const Edge& c : candidates) {
    bool free = true;
    for (int p = 0; p < n && free; ++p) free = !points.inside_segment(p, c.first, c.second);
    for (std::size_t e = 0; e < edges.size() && free; ++e) free = !points.cross_properly(c, edges[e]);
    if (!free) continue;
    edges.push_back(c);
    neighbours[c.first].insert(c.second);
    neighbours[c.second].insert(c.first);
  }

  // The bounded faces of a maximal plane graph are its empty triangles.
  CutFace result;
  const int face_orientation = points.orientation(0, 1, 2);
  for (const Edge& e : edges)
    for (const int k : neighbours[e.first]) {
      if (k <= e.second || !neighbours[e.second].count(k)) continue;
      const int orientation = points.orientation(e.first, e.second, k);
      if (orientation == 0) continue;
      bool empty = true;
      for (int p = 0; p < n && empty; ++p)
        empty = p == e.first || p == e.second || p == k || points.orientation(e.first, e.second, p) != orientation ||
                points.orientation(e.second, k, p) != orientation || points.orientation(k, e.first, p) != orientation;
      if (!empty) continue;
      result.triangles.push_back(orientation == face_orientation ? std::array<int, 3>{e.first, e.second, k}
                                                                 : std::array<int, 3>{e.first, k, e.second});
    }
  result.points = points.release();
  return result;
}

}  // namespace meshprep::detail
