#include "meshprep/quality/self_intersections.h"

#include "meshprep/quality/triangle_bvh.h"
#include "meshprep/quality/triangle_intersection.h"

#include "neighbour_pairs.h"
#include "plane_separation.h"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <array>
#include <utility>

namespace meshprep {
namespace {

bool has_area(const SoupView& soup, const Triangle& t) {
  return triangle_has_area(soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]);
}

std::array<Vec3, 3> corners(const SoupView& soup, std::size_t f) {
  const Triangle& t = soup.triangles[f];
  return {soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]};
}

bool faces_intersect(const SoupView& soup, const Triangle& a, const Triangle& b) {
  const auto& P = soup.points;
  int shared = 0, ia = -1, ib = -1;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      if (a[i] == b[k]) {
        ++shared;
        if (ia < 0) {
          ia = i;
          ib = k;
        }
      }
  switch (shared) {
    case 0:
      return triangles_intersect(P[a[0]], P[a[1]], P[a[2]], P[b[0]], P[b[1]], P[b[2]]);
    case 1: {  // an intersection away from the shared corner crosses an opposite edge
      const Vec3 &a1 = P[a[(ia + 1) % 3]], &a2 = P[a[(ia + 2) % 3]];
      const Vec3 &b1 = P[b[(ib + 1) % 3]], &b2 = P[b[(ib + 2) % 3]];
      return segment_intersects_triangle(a1, a2, P[b[0]], P[b[1]], P[b[2]]) ||
             segment_intersects_triangle(b1, b2, P[a[0]], P[a[1]], P[a[2]]);
    }
    case 2: {  // neighbours across an edge meet elsewhere only if they fold onto each other
      auto opposite = [](const Triangle& t, const Triangle& other) {
        for (auto v : t)
          if (v != other[0] && v != other[1] && v != other[2]) return v;
        return t[0];
      };
      const auto oa = opposite(a, b), ob = opposite(b, a);
      std::uint32_t s[2];
      int n = 0;
      for (auto v : a)
        if (v != oa) s[n++] = v;
      return neighbours_fold(P[s[0]], P[s[1]], P[oa], P[ob]);
    }
    default:  // the same three vertices: a duplicated face
      return true;
  }
}

}  // namespace

SelfIntersections find_self_intersections(const SoupView& soup, std::size_t cap) {
  const std::size_t n = soup.triangles.size();
  std::vector<char> valid(n);
  for (std::size_t f = 0; f < n; ++f) valid[f] = has_area(soup, soup.triangles[f]) ? 1 : 0;
  // Each thread keeps the pairs it found; sorted together afterwards, whatever the threads did.
  struct Found {
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    std::size_t tests = 0;
  };
  tbb::enumerable_thread_specific<Found> found;
  auto test = [&](std::size_t i, std::size_t j) {
    Found& local = found.local();
    ++local.tests;
    if (faces_intersect(soup, soup.triangles[i], soup.triangles[j])) local.pairs.emplace_back(i, j);
  };
  // Faces with corners in common around each vertex; the others by their boxes.
  detail::for_each_neighbour_pair(soup, valid, test);
  // Boxes overlap far more often than the triangles' planes let them meet (long thin triangles
  // have large boxes): the certain cases are settled in floating point, before the exact test.
  TriangleBvh(soup).for_each_overlapping_pair_apart([&](std::size_t i, std::size_t j) {
    if (valid[i] && valid[j] && !detail::certainly_separated_by_a_plane(corners(soup, i), corners(soup, j))) test(i, j);
  });
  SelfIntersections result;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (const Found& local : found) {
    pairs.insert(pairs.end(), local.pairs.begin(), local.pairs.end());
    result.exact_tests += local.tests;
  }
  std::sort(pairs.begin(), pairs.end());
  result.capped = cap > 0 && pairs.size() > cap;
  if (result.capped) pairs.resize(cap);
  result.count = pairs.size();
  result.pairs = std::move(pairs);
  return result;
}

}  // namespace meshprep
