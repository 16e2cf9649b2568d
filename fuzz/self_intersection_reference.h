#pragma once
/// \file self_intersection_reference.h
/// A brute-force reference for find_self_intersections on soups whose coordinates are small
/// integers: every pair of faces, the same rules for faces with corners in common (self_intersections.h),
/// each decided by separating axes in exact 64-bit integer arithmetic. It shares no code and no
/// method with quality/ (which uses orientation signs and a broad phase).

#include "meshprep/core/mesh.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace meshprep::fuzz {

using IntVec = std::array<std::int64_t, 3>;

inline IntVec minus(const IntVec& a, const IntVec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline IntVec cross(const IntVec& a, const IntVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline std::int64_t dot(const IntVec& a, const IntVec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline bool is_zero(const IntVec& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

/// Do the convex hulls of two point sets (each a segment or a triangle with area) meet? By the
/// separating axis theorem they are disjoint iff their projections on some axis are: for
/// segments and triangles it suffices to try the normals, the cross products of an edge of one
/// with an edge of the other, and each normal crossed with every edge (the axes within a common
/// plane). Coordinates up to about 1000 keep every product exact.
inline bool convex_hulls_meet(const std::vector<IntVec>& a, const std::vector<IntVec>& b) {
  auto edges_of = [](const std::vector<IntVec>& p) {
    std::vector<IntVec> edges;
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = i + 1; j < p.size(); ++j) edges.push_back(minus(p[j], p[i]));
    return edges;
  };
  const std::vector<IntVec> ea = edges_of(a), eb = edges_of(b);
  std::vector<IntVec> normals;
  if (a.size() == 3) normals.push_back(cross(ea[0], ea[1]));
  if (b.size() == 3) normals.push_back(cross(eb[0], eb[1]));
  std::vector<IntVec> axes = normals;
  for (const IntVec& e : ea)
    for (const IntVec& f : eb) axes.push_back(cross(e, f));
  for (const IntVec& n : normals) {
    for (const IntVec& e : ea) axes.push_back(cross(n, e));
    for (const IntVec& f : eb) axes.push_back(cross(n, f));
  }
  for (const IntVec& axis : axes) {
    if (is_zero(axis)) continue;
    auto range = [&](const std::vector<IntVec>& p) {
      std::int64_t lo = dot(axis, p[0]), hi = lo;
      for (const IntVec& q : p) lo = std::min(lo, dot(axis, q)), hi = std::max(hi, dot(axis, q));
      return std::pair(lo, hi);
    };
    const auto [a_lo, a_hi] = range(a);
    const auto [b_lo, b_hi] = range(b);
    if (a_hi < b_lo || b_hi < a_lo) return false;
  }
  return true;
}

/// The intersecting pairs (i < j, sorted) of faces with area, by the rules of self_intersections.h:
/// faces with no corner in common intersect if they meet; with one corner, if the edge of either
/// opposite it meets the other; with an edge, if they fold onto each other (coplanar, the far
/// corners on the same side of it); with three corners, always.
inline std::vector<std::pair<std::size_t, std::size_t>> reference_self_intersections(
    const std::vector<IntVec>& points, const std::vector<Triangle>& faces) {
  auto corners = [&](const Triangle& t) { return std::vector<IntVec>{points[t[0]], points[t[1]], points[t[2]]}; };
  auto has_area = [&](const Triangle& t) {
    return !is_zero(cross(minus(points[t[1]], points[t[0]]), minus(points[t[2]], points[t[0]])));
  };
  // The corners of t but those in `skip`, in order.
  auto others = [](const Triangle& t, const std::vector<std::uint32_t>& skip) {
    std::vector<std::uint32_t> rest;
    for (auto v : t)
      if (std::find(skip.begin(), skip.end(), v) == skip.end()) rest.push_back(v);
    return rest;
  };
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (std::size_t j = i + 1; j < faces.size(); ++j) {
      const Triangle &f = faces[i], &g = faces[j];
      if (!has_area(f) || !has_area(g)) continue;
      std::vector<std::uint32_t> common;
      for (auto v : f)
        if (std::find(g.begin(), g.end(), v) != g.end()) common.push_back(v);
      bool meet = false;
      if (common.empty()) {
        meet = convex_hulls_meet(corners(f), corners(g));
      } else if (common.size() == 1) {
        const auto rest_f = others(f, common), rest_g = others(g, common);
        meet = convex_hulls_meet({points[rest_f[0]], points[rest_f[1]]}, corners(g)) ||
               convex_hulls_meet({points[rest_g[0]], points[rest_g[1]]}, corners(f));
      } else if (common.size() == 2) {
        const IntVec &s0 = points[common[0]], &s1 = points[common[1]];
        const IntVec &far_f = points[others(f, common)[0]], &far_g = points[others(g, common)[0]];
        const IntVec n_f = cross(minus(s1, s0), minus(far_f, s0)), n_g = cross(minus(s1, s0), minus(far_g, s0));
        meet = dot(n_f, minus(far_g, s0)) == 0 && dot(n_f, n_g) > 0;
      } else {
        meet = true;
      }
      if (meet) pairs.emplace_back(i, j);
    }
  return pairs;
}

}  // namespace meshprep::fuzz
