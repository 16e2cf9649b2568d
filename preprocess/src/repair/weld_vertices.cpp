#include "repair/weld_vertices.h"

#include "meshprep/core/union_find.h"
#include "meshprep/quality/face_edges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace meshprep::detail {
namespace {

// Teschner et al.'s spatial hash, in unsigned arithmetic (wraps instead of overflowing).
struct CellHash {
  std::size_t operator()(const std::array<std::int64_t, 3>& c) const {
    const auto u = [](std::int64_t x) { return static_cast<std::uint64_t>(x); };
    return static_cast<std::size_t>(u(c[0]) * 73856093u ^ u(c[1]) * 19349663u ^ u(c[2]) * 83492791u);
  }
};

// Cell coordinates are whole numbers of `distance`: beyond 2^53 of them they stop being exact and
// then overflow an int64, so a distance that small against the coordinates welds exact copies only.
bool grid_fits(const TriangleSoup& soup, double distance) {
  double largest = 0;
  for (const Vec3& p : soup.points) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  return largest / distance < 9e15;
}

// Joins every pair of used vertices within `distance`: exact copies through a sort, near ones
// through a grid of cells `distance` wide (a pair lies in neighbouring cells).
std::size_t join_close(const TriangleSoup& soup, const std::vector<char>& used, double distance, UnionFind& clusters) {
  std::vector<std::uint32_t> order;
  for (std::uint32_t v = 0; v < soup.points.size(); ++v)
    if (used[v]) order.push_back(v);
  std::size_t joined = 0;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const Vec3 &p = soup.points[a], &q = soup.points[b];
    return std::tie(p.x(), p.y(), p.z(), a) < std::tie(q.x(), q.y(), q.z(), b);
  });
  for (std::size_t i = 1; i < order.size(); ++i)
    if (soup.points[order[i]] == soup.points[order[i - 1]]) joined += clusters.unite(order[i], order[i - 1]);
  if (!(distance > 0) || !grid_fits(soup, distance)) return joined;
  std::unordered_map<std::array<std::int64_t, 3>, std::vector<std::uint32_t>, CellHash> cells;
  const auto cell_of = [distance](const Vec3& p) {
    return std::array<std::int64_t, 3>{static_cast<std::int64_t>(std::floor(p.x() / distance)),
                                       static_cast<std::int64_t>(std::floor(p.y() / distance)),
                                       static_cast<std::int64_t>(std::floor(p.z() / distance))};
  };
  for (const std::uint32_t v : order) cells[cell_of(soup.points[v])].push_back(v);
  const double squared = distance * distance;
  for (const std::uint32_t v : order) {
    const std::array<std::int64_t, 3> c = cell_of(soup.points[v]);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto found = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (found == cells.end()) continue;
          for (const std::uint32_t w : found->second)
            if (w > v && (soup.points[w] - soup.points[v]).squaredNorm() <= squared) joined += clusters.unite(v, w);
        }
  }
  return joined;
}

}  // namespace

WeldCounts weld_vertices(TriangleSoup& soup, double distance) {
  WeldCounts counts;
  std::vector<char> used(soup.points.size(), 0);
  for (const Triangle& t : soup.triangles)
    for (const std::uint32_t v : t) used[v] = 1;
  UnionFind clusters(soup.points.size());
  counts.welded_vertices = join_close(soup, used, distance, clusters);

  // Faces naming a vertex twice go. Of faces on the same three vertices facing the same way, the
  // first in the file stays. Faces on them facing both ways, where every edge of theirs has two
  // faces besides them, are a wall two solids share (each faces into the other): all go, and the
  // solids become one. Elsewhere (a solid with one face written twice) the first stays.
  std::vector<Triangle> faces;
  struct Copies {
    std::size_t first;  // in faces
    std::size_t count;
    bool forward, both_ways;
  };
  std::map<std::array<std::uint32_t, 3>, Copies> seen;
  std::unordered_map<std::uint64_t, std::size_t> edge_uses;
  for (Triangle t : soup.triangles) {
    for (std::uint32_t& v : t) v = clusters.find(v);
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      ++counts.degenerate_faces;
      continue;
    }
    for (int i = 0; i < 3; ++i) ++edge_uses[edge_key(t[i], t[(i + 1) % 3])];
    std::array<std::uint32_t, 3> sorted{t[0], t[1], t[2]};
    std::sort(sorted.begin(), sorted.end());
    // (a, b, c) is a rotation of its sorted order iff an even number of its pairs are inverted.
    const bool forward = ((t[0] > t[1]) + (t[1] > t[2]) + (t[0] > t[2])) % 2 == 0;
    const auto [it, added] = seen.emplace(sorted, Copies{faces.size(), 1, forward, false});
    if (!added) {
      ++counts.duplicate_faces;
      ++it->second.count;
      it->second.both_ways = it->second.both_ways || it->second.forward != forward;
      continue;
    }
    faces.push_back(t);
  }
  std::vector<char> wall(faces.size(), 0);
  for (const auto& [vertices, copies] : seen) {
    if (!copies.both_ways) continue;
    const auto others = [&](std::uint32_t a, std::uint32_t b) { return edge_uses[edge_key(a, b)] - copies.count; };
    if (others(vertices[0], vertices[1]) >= 2 && others(vertices[1], vertices[2]) >= 2 &&
        others(vertices[0], vertices[2]) >= 2)
      wall[copies.first] = 1, ++counts.duplicate_faces;
  }
  std::size_t kept = 0;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (!wall[f]) faces[kept++] = faces[f];
  faces.resize(kept);

  std::vector<std::uint32_t> renumber(soup.points.size(), UINT32_MAX);
  std::vector<Vec3> points;
  for (Triangle& t : faces)
    for (std::uint32_t& v : t) {
      if (renumber[v] == UINT32_MAX) {
        renumber[v] = static_cast<std::uint32_t>(points.size());
        points.push_back(soup.points[v]);
      }
      v = renumber[v];
    }
  counts.unused_vertices = soup.points.size() - points.size() - counts.welded_vertices;
  soup.points = std::move(points);
  soup.triangles = std::move(faces);
  return counts;
}

}  // namespace meshprep::detail
