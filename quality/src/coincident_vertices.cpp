#include "meshprep/quality/coincident_vertices.h"

#include "meshprep/quality/face_edges.h"

#include <algorithm>
#include <cstdint>
#include <tuple>

namespace meshprep {

namespace {

// The vertices on an edge that only one face has (a seam of a split-vertex file is such an edge).
std::vector<char> border_vertices(const TriangleSoup& surface) {
  const std::vector<FaceEdge> edges = sorted_face_edges(surface);
  std::vector<char> border(surface.points.size(), 0);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].key == edges[i].key) ++j;
    if (j - i == 1) border[edges[i].lo()] = border[edges[i].hi()] = 1;
    i = j;
  }
  return border;
}

}  // namespace

CoincidentVertices find_coincident_vertices(const TriangleSoup& surface) {
  const std::vector<char> border = border_vertices(surface);
  std::vector<std::uint32_t> order;
  for (std::uint32_t v = 0; v < surface.points.size(); ++v)
    if (border[v]) order.push_back(v);
  const auto before = [&](std::uint32_t a, std::uint32_t b) {
    const Vec3 &p = surface.points[a], &q = surface.points[b];
    return std::tie(p.x(), p.y(), p.z(), a) < std::tie(q.x(), q.y(), q.z(), b);
  };
  std::sort(order.begin(), order.end(), before);
  std::vector<std::uint32_t> target(surface.points.size());
  for (std::uint32_t v = 0; v < target.size(); ++v) target[v] = v;
  std::vector<char> coincident(surface.points.size(), 0);
  CoincidentVertices w;
  for (std::size_t i = 1; i < order.size(); ++i)
    if (surface.points[order[i]] == surface.points[order[i - 1]]) {
      target[order[i]] = target[order[i - 1]];  // the smallest index of the run
      coincident[order[i]] = coincident[order[i - 1]] = 1;
      ++w.merged;
    }
  if (w.merged == 0) return w;
  w.welded = surface;
  for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
    Triangle& t = w.welded.triangles[f];
    bool at_coincident = false;
    for (std::uint32_t& v : t) {
      at_coincident = at_coincident || coincident[v];
      v = target[v];
    }
    if (at_coincident) w.faces.push_back(f);
  }
  return w;
}

}  // namespace meshprep
