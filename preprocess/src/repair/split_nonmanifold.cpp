#include "repair/split_nonmanifold.h"

#include "meshprep/core/union_find.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace meshprep::detail {
namespace {

// Face f's corner at vertex v, as an index into the 3 * faces corners.
std::uint32_t corner(const TriangleSoup& soup, std::uint32_t f, std::uint32_t v) {
  const Triangle& t = soup.triangles[f];
  return 3 * f + (t[0] == v ? 0u : t[1] == v ? 1u : 2u);
}

// The faces on one non-manifold edge (uses [begin, end) of one key), paired across the wedges of
// solid they bound. Around the edge a -> b (a the smaller index), a face running a -> b has its
// normal (b - a) x (c - a) turned a quarter towards increasing angle, so the solid behind it lies
// towards decreasing angle: it pairs with its angular predecessor if that one runs b -> a. Two
// outward boxes on one edge thus become two closed sheets (an inward pair would join across the
// empty wedges, which is still manifold). Faces left without a partner are left unpaired.
std::vector<std::pair<std::uint32_t, std::uint32_t>> pair_around_edge(const TriangleSoup& soup, const FaceEdge* begin,
                                                                      const FaceEdge* end) {
  const Vec3& a = soup.points[begin->lo()];
  const Vec3 axis = (soup.points[begin->hi()] - a).normalized();
  const Vec3 u = axis.unitOrthogonal(), v = axis.cross(u);
  struct Sheet {
    double angle;
    std::uint32_t face;
    bool forward;
  };
  std::vector<Sheet> sheets;
  for (const FaceEdge* use = begin; use != end; ++use) {
    const Triangle& t = soup.triangles[use->face];
    std::uint32_t third = t[0];
    for (const std::uint32_t w : t)
      if (w != use->lo() && w != use->hi()) third = w;
    const Vec3 arm = soup.points[third] - a;
    sheets.push_back({std::atan2(arm.dot(v), arm.dot(u)), use->face, use->forward});
  }
  std::sort(sheets.begin(), sheets.end(), [](const Sheet& x, const Sheet& y) { return x.angle < y.angle; });
  const std::size_t n = sheets.size();
  std::vector<char> paired(n, 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t before = (i + n - 1) % n;
    if (!sheets[i].forward || paired[i] || sheets[before].forward || paired[before]) continue;
    paired[i] = paired[before] = 1;
    pairs.emplace_back(sheets[i].face, sheets[before].face);
  }
  return pairs;
}

}  // namespace

// The faces' corners at each vertex are joined across the edges that stay manifold (two faces,
// or a pair chosen above); each resulting group is one fan, and every group after a vertex's
// first gets a copy of the vertex.
SplitCounts split_nonmanifold(TriangleSoup& soup, const std::vector<FaceEdge>& uses) {
  SplitCounts counts;
  UnionFind fans(3 * soup.triangles.size());
  const auto join = [&](const FaceEdge& edge, std::uint32_t f, std::uint32_t g) {
    fans.unite(corner(soup, f, edge.lo()), corner(soup, g, edge.lo()));
    fans.unite(corner(soup, f, edge.hi()), corner(soup, g, edge.hi()));
  };
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i == 2) {
      join(uses[i], uses[i].face, uses[i + 1].face);
    } else if (j - i > 2) {
      ++counts.split_edges;
      for (const auto& [f, g] : pair_around_edge(soup, uses.data() + i, uses.data() + j)) join(uses[i], f, g);
    }
    i = j;
  }
  std::vector<std::uint32_t> vertex_of_fan(3 * soup.triangles.size(), UINT32_MAX);
  std::vector<char> taken(soup.points.size(), 0), split(soup.points.size(), 0);
  for (std::uint32_t c = 0; c < vertex_of_fan.size(); ++c) {
    std::uint32_t& v = soup.triangles[c / 3][c % 3];
    std::uint32_t& fan_vertex = vertex_of_fan[fans.find(c)];
    if (fan_vertex == UINT32_MAX) {
      if (!taken[v]) {
        taken[v] = 1;
        fan_vertex = v;
      } else {
        counts.split_vertices += !split[v];
        split[v] = 1;
        fan_vertex = static_cast<std::uint32_t>(soup.points.size());
        soup.points.push_back(soup.points[v]);
      }
    }
    v = fan_vertex;
  }
  return counts;
}

}  // namespace meshprep::detail
