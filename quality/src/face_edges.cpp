#include "meshprep/quality/face_edges.h"

#include <algorithm>

namespace meshprep {

namespace {

bool names_three_vertices(const Triangle& t) { return t[0] != t[1] && t[1] != t[2] && t[0] != t[2]; }

}  // namespace

// A counting sort by the smaller vertex, then each vertex's run (a few edges: its degree) sorted
// alone, costs a third of one comparison sort of all 3 x faces edges, and those are most of what a
// clean surface costs topology and repair.
std::vector<FaceEdge> sorted_face_edges(const SoupView& soup) {
  // Sized by the largest index the faces name, not by the points: the sort asks nothing of them.
  std::size_t vertices = 0;
  for (const Triangle& t : soup.triangles)
    vertices = std::max(vertices, std::size_t{*std::max_element(t.begin(), t.end())} + 1);
  std::vector<std::size_t> run_end(vertices + 1, 0);  // shifted by one: run_end[v + 1]
  for (const Triangle& t : soup.triangles)
    if (names_three_vertices(t))
      for (int c = 0; c < 3; ++c) ++run_end[std::min(t[c], t[(c + 1) % 3]) + 1];
  for (std::size_t v = 1; v < run_end.size(); ++v) run_end[v] += run_end[v - 1];
  std::vector<FaceEdge> edges(run_end.back());
  std::vector<std::size_t> next(run_end.begin(), run_end.end() - 1);  // where each run's next edge goes
  for (std::uint32_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    if (!names_three_vertices(t)) continue;
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t a = t[c], b = t[(c + 1) % 3];
      edges[next[std::min(a, b)]++] = {edge_key(a, b), f, a < b};
    }
  }
  const auto before = [](const FaceEdge& x, const FaceEdge& y) {
    return x.key < y.key || (x.key == y.key && x.face < y.face);
  };
  for (std::size_t v = 0; v + 1 < run_end.size(); ++v)
    std::sort(edges.begin() + static_cast<std::ptrdiff_t>(run_end[v]),
              edges.begin() + static_cast<std::ptrdiff_t>(run_end[v + 1]), before);
  return edges;
}

}  // namespace meshprep
