#include "meshprep/quality/triangle_bvh.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace meshprep {
namespace {

constexpr std::uint32_t kLeafSize = 4;
constexpr int kMaxDepth = 64;  // median splits: depth is log2(n / kLeafSize) + 1
constexpr int kParallelDepth = 10;  // node pairs this deep in the self-traversal still fork
constexpr int kParallelBuildDepth = 4;  // subtrees this deep are still built two at a time

// Nodes of the subtree over m triangles: a leaf, or a node over two halves (floor(m / 2) left).
// Where the build forks, the right subtree's place in the preorder is known before the left is built.
std::uint32_t subtree_nodes(std::uint32_t m) {
  return m <= kLeafSize ? 1 : 1 + subtree_nodes(m / 2) + subtree_nodes(m - m / 2);
}

using Corners = std::array<std::uint32_t, 3>;

// The point indices of `t`, ascending, each once, padded with `none` (the largest value).
Corners sorted_corners(const Triangle& t, std::uint32_t none) {
  Corners c{t[0], t[1], t[2]};
  std::sort(c.begin(), c.end());
  if (c[2] == c[1]) c[2] = none;
  if (c[1] == c[0]) c[1] = c[2], c[2] = none;
  return c;
}

// The values both ascending lists hold, ascending, padded with `none`.
Corners common_corners(const Corners& a, const Corners& b, std::uint32_t none) {
  Corners both{none, none, none};
  std::set_intersection(a.begin(), std::find(a.begin(), a.end(), none), b.begin(), std::find(b.begin(), b.end(), none),
                        both.begin());
  return both;
}

// The float nearest to x on the side of `towards` (-inf or +inf) that is not past x: x itself if
// it is a float. Beyond the float range, the largest float (a lower bound of a larger x) or the
// infinity on that side.
float rounded_outwards(double x, float towards) {
  constexpr double kLargest = std::numeric_limits<float>::max();
  if (x > kLargest) return towards > 0 ? towards : std::numeric_limits<float>::max();
  if (x < -kLargest) return towards < 0 ? towards : -std::numeric_limits<float>::max();
  const float f = static_cast<float>(x);  // (NaN stays NaN)
  return (towards < 0 ? f > x : f < x) ? std::nextafter(f, towards) : f;
}

bool triangles_share_a_corner(const Triangle& a, const Triangle& b) {
  for (auto u : a)
    for (auto v : b)
      if (u == v) return true;
  return false;
}

}  // namespace

Box3 bounding_box(const SoupView& soup) {
  Box3 box;
  box.setEmpty();
  for (const Triangle& t : soup.triangles)
    for (auto v : t) box.extend(soup.points[v]);
  return box;
}

// Real-Time Collision Detection (Ericson 2005), section 5.1.5: classify p against the Voronoi
// regions of the triangle's vertices and edges; otherwise project onto the face.
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = va + vb + vc;
  if (!(denom > 0)) {  // degenerate (collinear) triangle: fall back to its corners
    const Vec3* best = &a;
    for (const Vec3* q : {&b, &c})
      if ((p - *q).squaredNorm() < (p - *best).squaredNorm()) best = q;
    return *best;
  }
  return a + ab * (vb / denom) + ac * (vc / denom);
}

Vec3 closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  if (!(length2 > 0)) return a;
  return a + std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) * ab;
}

TriangleBvh::FloatBox TriangleBvh::FloatBox::around(const Box3& box) {
  constexpr float kInfinity = std::numeric_limits<float>::infinity();
  FloatBox out;
  for (int k = 0; k < 3; ++k) {
    out.min[k] = rounded_outwards(box.min()[k], -kInfinity);
    out.max[k] = rounded_outwards(box.max()[k], kInfinity);
  }
  return out;
}

TriangleBvh::FloatBox TriangleBvh::FloatBox::merged(const FloatBox& other) const {
  FloatBox out;
  for (int k = 0; k < 3; ++k) {
    out.min[k] = std::min(min[k], other.min[k]);
    out.max[k] = std::max(max[k], other.max[k]);
  }
  return out;
}

Box3 TriangleBvh::FloatBox::widened() const {
  return Box3(Vec3(min[0], min[1], min[2]), Vec3(max[0], max[1], max[2]));
}

TriangleBvh::TriangleBvh(const SoupView& soup) : soup_(soup) {
  static_assert(sizeof(Node) == 44, "a node is 11 words: see triangle_bvh.h");
  const auto n = static_cast<std::uint32_t>(soup.triangles.size());
  boxes_.resize(n);
  std::vector<Vec3> centroids(n);
  tbb::parallel_for(std::uint32_t(0), n, [&](std::uint32_t f) {
    Box3 box;
    box.setEmpty();
    for (auto v : soup.triangles[f]) box.extend(soup.points[v]);
    boxes_[f] = FloatBox::around(box);
    centroids[f] = box.center();
  });
  order_.resize(n);
  for (std::uint32_t f = 0; f < n; ++f) order_[f] = f;
  if (n == 0) return;
  nodes_.resize(subtree_nodes(n));
  build(0, 0, n, centroids, 0);
}

// The subtree over order_[begin, end) into nodes_ from `index` on, in preorder (the node, its left
// subtree, its right subtree); returns the index after it. A node's box is its children's
// together: the same box as over all its triangles, from one pass per level fewer.
std::uint32_t TriangleBvh::build(std::uint32_t index, std::uint32_t begin, std::uint32_t end,
                                 const std::vector<Vec3>& centroids, int depth) {
  Node& node = nodes_[index];
  if (end - begin <= kLeafSize) {
    node.box = boxes_[order_[begin]];
    node.common = sorted_corners(soup_.triangles[order_[begin]], kNoCorner);
    for (std::uint32_t i = begin; i < end; ++i) {
      node.box = node.box.merged(boxes_[order_[i]]);
      node.common = common_corners(node.common, sorted_corners(soup_.triangles[order_[i]], kNoCorner), kNoCorner);
    }
    node.first_or_right = begin;
    node.count = end - begin;
    return index + 1;
  }
  Box3 centre_box;
  centre_box.setEmpty();
  for (std::uint32_t i = begin; i < end; ++i) centre_box.extend(centroids[order_[i]]);
  int axis = 0;
  centre_box.sizes().maxCoeff(&axis);
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](std::uint32_t x, std::uint32_t y) { return centroids[x][axis] < centroids[y][axis]; });
  const std::uint32_t left = index + 1;
  std::uint32_t right = 0, next = 0;
  if (depth < kParallelBuildDepth) {
    right = left + subtree_nodes(mid - begin);
    next = right + subtree_nodes(end - mid);
    tbb::parallel_invoke([&] { build(left, begin, mid, centroids, depth + 1); },
                         [&] { build(right, mid, end, centroids, depth + 1); });
  } else {
    right = build(left, begin, mid, centroids, depth + 1);
    next = build(right, mid, end, centroids, depth + 1);
  }
  node.first_or_right = right;
  node.box = nodes_[left].box.merged(nodes_[right].box);
  node.common = common_corners(nodes_[left].common, nodes_[right].common, kNoCorner);
  return next;
}

TriangleBvh::Hit TriangleBvh::closest_point(const Vec3& p) const {
  Hit best;
  best.squared_distance = std::numeric_limits<double>::infinity();
  if (nodes_.empty()) return best;
  // Each waiting node with its box's distance to p, measured once, when its parent was opened.
  struct Waiting {
    std::uint32_t node;
    double squared_distance;
  };
  Waiting stack[kMaxDepth * 2];
  int top = 0;
  stack[top++] = {0, 0.0};
  // A NaN distance is never beyond the best: such a node is opened, as it was before distances were kept.
  auto beyond_best = [&](double squared_distance) { return squared_distance >= best.squared_distance; };
  while (top > 0) {
    const Waiting waiting = stack[--top];
    if (beyond_best(waiting.squared_distance)) continue;  // the best has come closer since it was queued
    const Node& node = nodes_[waiting.node];
    if (node.count > 0) {
      for (std::uint32_t i = node.first_or_right; i < node.first_or_right + node.count; ++i) {
        const Triangle& t = soup_.triangles[order_[i]];
        const Vec3 q = closest_point_on_triangle(p, soup_.points[t[0]], soup_.points[t[1]], soup_.points[t[2]]);
        const double d2 = (q - p).squaredNorm();
        if (d2 < best.squared_distance || (d2 == best.squared_distance && order_[i] < best.face)) {
          best = {order_[i], q, d2};
        }
      }
      continue;
    }
    // Visit the nearer child first (pushed last) so that the bound shrinks early; a child already
    // beyond the best is not queued.
    const std::uint32_t left_child = waiting.node + 1, right_child = node.first_or_right;
    const Waiting left{left_child, nodes_[left_child].box.squared_exterior_distance(p)};
    const Waiting right{right_child, nodes_[right_child].box.squared_exterior_distance(p)};
    const bool left_first = left.squared_distance < right.squared_distance;
    for (const Waiting& child : {left_first ? right : left, left_first ? left : right})
      if (!beyond_best(child.squared_distance)) stack[top++] = child;
  }
  return best;
}

bool TriangleBvh::reaches_within(const Vec3& p, double squared_radius) const {
  if (nodes_.empty()) return false;
  std::uint32_t stack[kMaxDepth * 2];
  int top = 0;
  if (nodes_[0].box.squared_exterior_distance(p) <= squared_radius) stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t index = stack[--top];
    const Node& node = nodes_[index];
    if (node.count > 0) {
      for (std::uint32_t i = node.first_or_right; i < node.first_or_right + node.count; ++i) {
        const Triangle& t = soup_.triangles[order_[i]];
        const Vec3 q = closest_point_on_triangle(p, soup_.points[t[0]], soup_.points[t[1]], soup_.points[t[2]]);
        if ((q - p).squaredNorm() <= squared_radius) return true;
      }
      continue;
    }
    // The nearer child is pushed last, so searched first.
    const std::uint32_t left_child = index + 1, right_child = node.first_or_right;
    const double left = nodes_[left_child].box.squared_exterior_distance(p);
    const double right = nodes_[right_child].box.squared_exterior_distance(p);
    const bool left_first = left < right;
    for (const auto& [child, distance] : {left_first ? std::pair(right_child, right) : std::pair(left_child, left),
                                          left_first ? std::pair(left_child, left) : std::pair(right_child, right)})
      if (distance <= squared_radius) stack[top++] = child;
  }
  return false;
}

double ray_triangle(const Vec3& origin, const Vec3& direction, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a;
  const Vec3 p = direction.cross(ac);
  const double det = ab.dot(p);
  if (!(std::abs(det) > 0)) return std::numeric_limits<double>::infinity();
  const Vec3 s = origin - a;
  const double u = s.dot(p) / det;
  if (u < 0 || u > 1) return std::numeric_limits<double>::infinity();
  const Vec3 q = s.cross(ab);
  const double v = direction.dot(q) / det;
  if (v < 0 || u + v > 1) return std::numeric_limits<double>::infinity();
  const double t = ac.dot(q) / det;
  return t > 0 ? t : std::numeric_limits<double>::infinity();
}

namespace {

// Where the ray enters `box` (0 if it starts inside), or infinity if it misses it (slab test).
double ray_box(const Vec3& origin, const Vec3& inverse_direction, const Box3& box) {
  double near = 0, far = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    double t0 = (box.min()[k] - origin[k]) * inverse_direction[k], t1 = (box.max()[k] - origin[k]) * inverse_direction[k];
    if (std::isnan(t0) || std::isnan(t1)) continue;  // the ray runs in the slab's plane (0 * inf)
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
  }
  return near <= far ? near : std::numeric_limits<double>::infinity();
}

}  // namespace

TriangleBvh::RayHit TriangleBvh::first_hit(const Vec3& origin, const Vec3& direction, std::size_t skip_face) const {
  RayHit best{std::numeric_limits<double>::infinity(), 0};
  if (nodes_.empty()) return best;
  const Vec3 inverse = direction.cwiseInverse();
  std::uint32_t stack[kMaxDepth * 2];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t index = stack[--top];
    const Node& node = nodes_[index];
    if (!(ray_box(origin, inverse, node.box.widened()) < best.distance)) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.first_or_right; i < node.first_or_right + node.count; ++i) {
        if (order_[i] == skip_face) continue;
        const Triangle& t = soup_.triangles[order_[i]];
        const double d = ray_triangle(origin, direction, soup_.points[t[0]], soup_.points[t[1]], soup_.points[t[2]]);
        if (d < best.distance || (d == best.distance && order_[i] < best.face)) best = {d, order_[i]};
      }
      continue;
    }
    stack[top++] = index + 1;
    stack[top++] = node.first_or_right;
  }
  return best;
}

void TriangleBvh::for_each_overlapping(const Box3& box, const std::function<void(std::size_t)>& visit) const {
  if (nodes_.empty()) return;
  const FloatBox query = FloatBox::around(box);
  std::uint32_t stack[kMaxDepth * 2];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t index = stack[--top];
    const Node& node = nodes_[index];
    if (!node.box.intersects(query)) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.first_or_right; i < node.first_or_right + node.count; ++i)
        if (boxes_[order_[i]].intersects(query)) visit(order_[i]);
      continue;
    }
    stack[top++] = index + 1;
    stack[top++] = node.first_or_right;
  }
}

void TriangleBvh::for_each_overlapping_pair_apart(const std::function<void(std::size_t, std::size_t)>& visit) const {
  if (!nodes_.empty()) overlapping_pairs(0, 0, 0, visit);
}

// The pairs of node a and node b (a == b: the pairs within one node) that have no corner in
// common. Node pairs whose boxes are apart, or whose triangles all have one corner, are dropped
// whole; the larger node is split first.
void TriangleBvh::overlapping_pairs(std::uint32_t a, std::uint32_t b, int depth,
                                    const std::function<void(std::size_t, std::size_t)>& visit) const {
  const Node& x = nodes_[a];
  const Node& y = nodes_[b];
  if (common_corners(x.common, y.common, kNoCorner)[0] != kNoCorner) return;
  auto both = [&](auto first, auto second) {
    if (depth < kParallelDepth) tbb::parallel_invoke(first, second);
    else {
      first();
      second();
    }
  };
  auto visit_if_apart = [&](std::uint32_t i, std::uint32_t j) {
    const std::uint32_t fi = order_[i], fj = order_[j];
    if (boxes_[fi].intersects(boxes_[fj]) && !triangles_share_a_corner(soup_.triangles[fi], soup_.triangles[fj]))
      visit(std::min(fi, fj), std::max(fi, fj));
  };
  if (a == b) {
    if (x.count > 0) {
      for (std::uint32_t i = x.first_or_right; i < x.first_or_right + x.count; ++i)
        for (std::uint32_t j = i + 1; j < x.first_or_right + x.count; ++j) visit_if_apart(i, j);
      return;
    }
    both([&] { overlapping_pairs(a + 1, a + 1, depth + 1, visit); },
         [&] {
           overlapping_pairs(x.first_or_right, x.first_or_right, depth + 1, visit);
           overlapping_pairs(a + 1, x.first_or_right, depth + 1, visit);
         });
    return;
  }
  if (!x.box.intersects(y.box)) return;
  if (x.count > 0 && y.count > 0) {
    for (std::uint32_t i = x.first_or_right; i < x.first_or_right + x.count; ++i)
      for (std::uint32_t j = y.first_or_right; j < y.first_or_right + y.count; ++j) visit_if_apart(i, j);
    return;
  }
  // Split the node that is not a leaf, the larger (by box volume) if neither is.
  const bool split_x = y.count > 0 || (x.count == 0 && x.box.widened().volume() >= y.box.widened().volume());
  if (split_x)
    both([&] { overlapping_pairs(a + 1, b, depth + 1, visit); },
         [&] { overlapping_pairs(x.first_or_right, b, depth + 1, visit); });
  else
    both([&] { overlapping_pairs(a, b + 1, depth + 1, visit); },
         [&] { overlapping_pairs(a, y.first_or_right, depth + 1, visit); });
}

}  // namespace meshprep
