#include "repair/split_t_junctions.h"

#include "meshprep/quality/face_edges.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace meshprep::detail {

namespace {

// Each split leaves two shorter open edges that may hold further vertices: a seam refined k times
// on one side needs k rounds; past this many the rest stays for the hole filling.
constexpr int kMaxRounds = 64;

struct OpenEdge {
  std::uint32_t face, from, to;  // from -> to in the face's order
};

// The open vertices in cells of a uniform grid: the candidates near a point are those of the 27
// cells around its own.
class VertexGrid {
 public:
  VertexGrid(const std::vector<Vec3>& points, const std::vector<std::uint32_t>& vertices, double cell) : cell_(cell) {
    for (const std::uint32_t v : vertices) cells_[key(cell_of(points[v]))].push_back(v);
  }
  template <class Visit>
  void near(const Vec3& p, Visit&& visit) const {
    const Eigen::Vector3i c = cell_of(p);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(key(c + Eigen::Vector3i(dx, dy, dz)));
          if (it != cells_.end())
            for (const std::uint32_t v : it->second) visit(v);
        }
  }

 private:
  Eigen::Vector3i cell_of(const Vec3& p) const { return (p / cell_).array().floor().cast<int>(); }
  static std::uint64_t key(const Eigen::Vector3i& c) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.x()) & 0x1fffff) << 42) |
           (static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.y()) & 0x1fffff) << 21) |
           (static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.z()) & 0x1fffff));
  }
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

std::vector<OpenEdge> open_edges(const TriangleSoup& soup) {
  const std::vector<FaceEdge> edges = sorted_face_edges(soup);
  std::vector<OpenEdge> open;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].key == edges[i].key) ++j;
    if (j - i == 1) {
      const FaceEdge& e = edges[i];
      open.push_back(e.forward ? OpenEdge{e.face, e.lo(), e.hi()} : OpenEdge{e.face, e.hi(), e.lo()});
    }
    i = j;
  }
  return open;
}

// One round: each face with an open edge holding an open vertex is split at the vertex nearest
// the edge's start. Returns the faces split.
std::size_t split_round(TriangleSoup& soup, double distance) {
  const std::vector<OpenEdge> open = open_edges(soup);
  if (open.empty()) return 0;
  std::vector<std::uint32_t> vertices;
  std::vector<double> lengths;
  for (const OpenEdge& e : open) {
    vertices.push_back(e.from);
    vertices.push_back(e.to);
    lengths.push_back((soup.points[e.to] - soup.points[e.from]).norm());
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2), lengths.end());
  const double cell = std::max(lengths[lengths.size() / 2], 4 * distance);
  if (!(cell > 0)) return 0;
  const VertexGrid grid(soup.points, vertices, cell);
  // face -> (position along its open edge, the vertex, the edge)
  std::map<std::uint32_t, std::tuple<double, std::uint32_t, OpenEdge>> splits;
  for (const OpenEdge& e : open) {
    const Vec3 a = soup.points[e.from], b = soup.points[e.to];
    const double length = (b - a).norm();
    if (!(length > 2 * distance)) continue;
    std::set<std::uint32_t> seen;
    // Samples half a cell apart cover every cell within one cell of the edge.
    const int samples = static_cast<int>(std::ceil(2 * length / cell));
    for (int s = 0; s <= samples; ++s)
      grid.near(a + (b - a) * (static_cast<double>(s) / samples), [&](std::uint32_t v) {
        if (v == e.from || v == e.to || !seen.insert(v).second) return;
        const Vec3& m = soup.points[v];
        const double along = (m - a).dot(b - a) / length;  // distance from a along the edge
        if (along <= distance || along >= length - distance) return;
        if ((a + (b - a) * (along / length) - m).norm() > distance) return;
        const auto it = splits.find(e.face);
        if (it == splits.end() || along < std::get<0>(it->second)) splits[e.face] = {along, v, e};
      });
  }
  for (const auto& [face, split] : splits) {
    const auto& [along, m, e] = split;
    const Triangle t = soup.triangles[face];
    const std::uint32_t opposite = t[0] != e.from && t[0] != e.to ? t[0] : t[1] != e.from && t[1] != e.to ? t[1] : t[2];
    soup.triangles[face] = {e.from, m, opposite};
    soup.triangles.push_back({m, e.to, opposite});
    if (!soup.patches.empty()) soup.patches.push_back(soup.patches[face]);
  }
  return splits.size();
}

}  // namespace

std::size_t split_t_junctions(TriangleSoup& soup, double distance) {
  std::size_t total = 0;
  for (int round = 0; round < kMaxRounds; ++round) {
    const std::size_t split = split_round(soup, distance);
    if (split == 0) break;
    total += split;
  }
  return total;
}

}  // namespace meshprep::detail
