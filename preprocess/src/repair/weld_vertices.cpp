#include "repair/weld_vertices.h"

#include "meshprep/core/bucket_sort.h"
#include "meshprep/core/union_find.h"
#include "meshprep/quality/face_edges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace meshprep::detail {
namespace {

// Cell coordinates are whole numbers of `distance`: beyond 2^53 of them they stop being exact and
// then overflow an int64, so a distance that small against the coordinates welds exact copies only.
bool grid_fits(const TriangleSoup& soup, double distance) {
  double largest = 0;
  for (const Vec3& p : soup.points) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  return largest / distance < 9e15;
}

// Joins the exact copies among `vertices`, neighbours once sorted by position.
std::size_t join_copies(const TriangleSoup& soup, std::vector<std::uint32_t>& vertices, UnionFind& clusters) {
  std::sort(vertices.begin(), vertices.end(), [&](std::uint32_t a, std::uint32_t b) {
    const Vec3 &p = soup.points[a], &q = soup.points[b];
    return std::tie(p.x(), p.y(), p.z(), a) < std::tie(q.x(), q.y(), q.z(), b);
  });
  std::size_t joined = 0;
  for (std::size_t i = 1; i < vertices.size(); ++i)
    if (soup.points[vertices[i]] == soup.points[vertices[i - 1]])
      joined += clusters.unite(vertices[i], vertices[i - 1]);
  return joined;
}

// Joins every pair among `vertices` within `distance` (> 0), exact copies included, through a grid
// of cells `distance` wide: a pair lies in neighbouring cells.
std::size_t join_within(const TriangleSoup& soup, const std::vector<std::uint32_t>& vertices, double distance,
                        UnionFind& clusters) {
  // The vertices sorted by their cell (x, y, z): the cells of one column (x, y) are a run, and a
  // vertex's 27 neighbouring cells are the runs of 9 columns, each from (x + dx, y + dy, z - 1) on.
  struct Cell {
    std::int64_t x, y, z;
    std::uint32_t vertex;
    bool operator<(const Cell& o) const { return std::tie(x, y, z, vertex) < std::tie(o.x, o.y, o.z, o.vertex); }
  };
  std::vector<Cell> cells;
  cells.reserve(vertices.size());
  for (const std::uint32_t v : vertices) {
    const Vec3& p = soup.points[v];
    cells.push_back({static_cast<std::int64_t>(std::floor(p.x() / distance)),
                     static_cast<std::int64_t>(std::floor(p.y() / distance)),
                     static_cast<std::int64_t>(std::floor(p.z() / distance)), v});
  }
  std::sort(cells.begin(), cells.end());
  // As c goes through the cells in order, each column's start (x + dx, y + dy, z - 1) only moves
  // forward: nine cursors sweep the cells once, where a binary search per cell and column cost
  // most of a clean weld.
  std::array<std::vector<Cell>::const_iterator, 9> start;
  start.fill(cells.begin());
  const double squared = distance * distance;
  std::size_t joined = 0;
  for (const Cell& c : cells)
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const Cell from{c.x + dx, c.y + dy, c.z - 1, 0};
        auto& column = start[static_cast<std::size_t>(3 * (dx + 1) + dy + 1)];
        while (column != cells.end() && *column < from) ++column;
        for (auto it = column; it != cells.end() && it->x == from.x && it->y == from.y && it->z <= c.z + 1; ++it)
          if (it->vertex > c.vertex &&
              (soup.points[it->vertex] - soup.points[c.vertex]).squaredNorm() <= squared)
            joined += clusters.unite(c.vertex, it->vertex);
      }
  return joined;
}

// Joins every pair of used vertices within `distance`, or, where the grid would not hold the
// coordinates (or `distance` is 0), the exact copies only. Each cluster's root is its lowest
// index (union_find.h), whichever pairs join it.
std::size_t join_close(const TriangleSoup& soup, const std::vector<char>& used, double distance, UnionFind& clusters) {
  std::vector<std::uint32_t> vertices;
  for (std::uint32_t v = 0; v < soup.points.size(); ++v)
    if (used[v]) vertices.push_back(v);
  if (distance > 0 && grid_fits(soup, distance)) return join_within(soup, vertices, distance, clusters);
  return join_copies(soup, vertices, clusters);
}

// The used vertices on an edge that one face alone uses, once `clusters` has joined the copies:
// every member of such a vertex's cluster. A face naming a vertex twice has no edges.
std::vector<std::uint32_t> open_edge_vertices(const TriangleSoup& soup, UnionFind& clusters) {
  std::unordered_map<std::uint64_t, std::uint32_t> uses;
  const auto corners = [&](const Triangle& t) {
    return Triangle{clusters.find(t[0]), clusters.find(t[1]), clusters.find(t[2])};
  };
  for (const Triangle& face : soup.triangles) {
    const Triangle t = corners(face);
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
    for (int i = 0; i < 3; ++i) ++uses[edge_key(t[i], t[(i + 1) % 3])];
  }
  std::vector<char> open_root(soup.points.size(), 0);
  for (const Triangle& face : soup.triangles) {
    const Triangle t = corners(face);
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
    for (int i = 0; i < 3; ++i)
      if (uses[edge_key(t[i], t[(i + 1) % 3])] == 1) open_root[t[i]] = open_root[t[(i + 1) % 3]] = 1;
  }
  std::vector<std::uint32_t> vertices;
  std::vector<char> listed(soup.points.size(), 0);
  for (const Triangle& face : soup.triangles)
    for (const std::uint32_t v : face)
      if (open_root[clusters.find(v)] && !listed[v]) {
        listed[v] = 1;
        vertices.push_back(v);
      }
  return vertices;
}

using Corners = std::array<std::uint32_t, 3>;

// Each face's sorted corners and index, sorted: faces on the same three vertices are neighbours,
// in their order in the file. Sorted by their smallest corner's runs (bucket_sort.h).
std::vector<std::pair<Corners, std::uint32_t>> by_corners(const std::vector<Triangle>& faces) {
  using Entry = std::pair<Corners, std::uint32_t>;
  std::vector<Entry> order(faces.size());
  for (std::uint32_t f = 0; f < faces.size(); ++f) {
    Corners sorted = faces[f];
    std::sort(sorted.begin(), sorted.end());
    order[f] = {sorted, f};
  }
  sort_by_buckets(order, [](const Entry& e) { return e.first[0]; }, std::less<Entry>());
  return order;
}

}  // namespace

WeldCounts weld_vertices(TriangleSoup& soup, double distance, WeldScope scope) {
  WeldCounts counts;
  std::vector<char> used(soup.points.size(), 0);
  for (const Triangle& t : soup.triangles)
    for (const std::uint32_t v : t) used[v] = 1;
  UnionFind clusters(soup.points.size());
  if (scope == WeldScope::everywhere) {
    counts.welded_vertices = join_close(soup, used, distance, clusters);
  } else {
    counts.welded_vertices = join_close(soup, used, 0, clusters);
    const std::vector<std::uint32_t> open = open_edge_vertices(soup, clusters);
    counts.input_closed = open.empty();
    if (distance > 0 && !open.empty() && grid_fits(soup, distance))
      counts.welded_vertices += join_within(soup, open, distance, clusters);
  }

  // Faces naming a vertex twice go. Of faces on the same three vertices facing the same way, the
  // first in the file stays. Faces on them facing both ways, where every edge of theirs has two
  // faces besides them, are a wall two solids share (each faces into the other): all go, and the
  // solids become one. Elsewhere (a solid with one face written twice) the first stays.
  std::vector<Triangle> faces;
  std::vector<int> patches;  // of the faces kept, when the soup has patches
  faces.reserve(soup.triangles.size());
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    Triangle t = soup.triangles[f];
    for (std::uint32_t& v : t) v = clusters.find(v);
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      ++counts.degenerate_faces;
    } else {
      faces.push_back(t);
      if (!soup.patches.empty()) patches.push_back(soup.patches[f]);
    }
  }
  const std::vector<std::pair<Corners, std::uint32_t>> order = by_corners(faces);
  // (a, b, c) is a rotation of its sorted order iff an even number of its pairs are inverted.
  const auto forward = [&faces](std::uint32_t f) {
    const Triangle& t = faces[f];
    return ((t[0] > t[1]) + (t[1] > t[2]) + (t[0] > t[2])) % 2 == 0;
  };
  std::vector<char> removed(faces.size(), 0);
  std::vector<std::pair<std::uint32_t, std::size_t>> both_ways;  // first face, copies
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i + 1;
    bool opposite = false;
    for (; j < order.size() && order[j].first == order[i].first; ++j) {
      removed[order[j].second] = 1;
      ++counts.duplicate_faces;
      opposite = opposite || forward(order[j].second) != forward(order[i].second);
    }
    if (opposite) both_ways.emplace_back(order[i].second, j - i);
    i = j;
  }
  if (!both_ways.empty()) {
    std::unordered_map<std::uint64_t, std::size_t> edge_uses, both_ways_uses;
    for (const Triangle& t : faces)
      for (int i = 0; i < 3; ++i) ++edge_uses[edge_key(t[i], t[(i + 1) % 3])];
    // The both-ways groups joined across their shared edges: a wall is such a region whose rim
    // other faces meet (the solids on either side). A region no other face meets is a part
    // written double-sided (each face once per orientation): its first copies stay.
    UnionFind regions(both_ways.size());
    std::unordered_map<std::uint64_t, std::size_t> group_on_edge;
    for (std::size_t g = 0; g < both_ways.size(); ++g) {
      const Triangle& t = faces[both_ways[g].first];
      for (int i = 0; i < 3; ++i) {
        const std::uint64_t e = edge_key(t[i], t[(i + 1) % 3]);
        both_ways_uses[e] += both_ways[g].second;
        const auto [it, first_on_edge] = group_on_edge.emplace(e, g);
        if (!first_on_edge) regions.unite(static_cast<std::uint32_t>(g), static_cast<std::uint32_t>(it->second));
      }
    }
    std::vector<char> meets_others(both_ways.size(), 0);
    for (const auto& [e, uses] : edge_uses)
      if (const auto it = group_on_edge.find(e); it != group_on_edge.end() && uses > both_ways_uses[e])
        meets_others[regions.find(static_cast<std::uint32_t>(it->second))] = 1;
    for (std::size_t g = 0; g < both_ways.size(); ++g) {
      const auto [first, copies] = both_ways[g];
      const Triangle& t = faces[first];
      bool wall = meets_others[regions.find(static_cast<std::uint32_t>(g))];
      for (int i = 0; i < 3; ++i) wall = wall && edge_uses[edge_key(t[i], t[(i + 1) % 3])] >= copies + 2;
      if (wall) removed[first] = 1, ++counts.duplicate_faces;
    }
  }
  soup.triangles = std::move(faces);
  soup.patches = std::move(patches);
  remove_faces(soup, removed);
  // The welded vertices are unused now too: they are counted apart.
  counts.unused_vertices = drop_unused_vertices(soup) - counts.welded_vertices;
  return counts;
}

void remove_faces(TriangleSoup& soup, const std::vector<char>& removed) {
  std::size_t kept = 0;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    if (!removed[f]) {
      if (!soup.patches.empty()) soup.patches[kept] = soup.patches[f];
      soup.triangles[kept++] = soup.triangles[f];
    }
  soup.triangles.resize(kept);
  if (!soup.patches.empty()) soup.patches.resize(kept);
}

std::size_t drop_unused_vertices(TriangleSoup& soup) {
  std::vector<std::uint32_t> renumber(soup.points.size(), UINT32_MAX);
  for (const Triangle& t : soup.triangles)
    for (const std::uint32_t v : t) renumber[v] = 0;
  std::size_t used = 0;
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    if (renumber[v] != UINT32_MAX) {
      renumber[v] = static_cast<std::uint32_t>(used);
      soup.points[used++] = soup.points[v];
    }
  const std::size_t dropped = soup.points.size() - used;
  soup.points.resize(used);
  for (Triangle& t : soup.triangles)
    for (std::uint32_t& v : t) v = renumber[v];
  return dropped;
}

}  // namespace meshprep::detail
