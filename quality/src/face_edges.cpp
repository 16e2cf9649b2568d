#include "meshprep/quality/face_edges.h"

#include <algorithm>

namespace meshprep {

// Ordered by key, whose high half is the smaller vertex: each edge is counted into its smaller
// vertex's run and placed there directly (a counting sort, in one array: the peak memory of
// topology and repair on a large surface), then each run, about a vertex's degree of edges, is
// sorted alone, which costs a third of one comparison sort of all 3 x faces edges.
std::vector<FaceEdge> sorted_face_edges(const SoupView& soup) {
  const auto for_each_edge = [&](auto&& visit) {
    for (std::uint32_t f = 0; f < soup.triangles.size(); ++f) {
      const Triangle& t = soup.triangles[f];
      if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
      for (int c = 0; c < 3; ++c) visit(t[c], t[(c + 1) % 3], f);
    }
  };
  // Runs sized by the largest vertex met, not by the points (a soup of faces alone is sorted too).
  std::size_t runs = 0;
  for_each_edge([&](std::uint32_t a, std::uint32_t b, std::uint32_t) { runs = std::max<std::size_t>(runs, std::min(a, b) + std::size_t{1}); });
  std::vector<std::size_t> run_end(runs + 1, 0);  // shifted by one: run_end[v + 1]
  for_each_edge([&](std::uint32_t a, std::uint32_t b, std::uint32_t) { ++run_end[std::min(a, b) + std::size_t{1}]; });
  for (std::size_t v = 1; v < run_end.size(); ++v) run_end[v] += run_end[v - 1];
  std::vector<FaceEdge> edges(run_end.back());
  std::vector<std::size_t> next(run_end.begin(), run_end.end() - 1);  // where each run's next edge goes
  for_each_edge([&](std::uint32_t a, std::uint32_t b, std::uint32_t f) { edges[next[std::min(a, b)]++] = {edge_key(a, b), f, a < b}; });
  for (std::size_t v = 0; v + 1 < run_end.size(); ++v)
    std::sort(edges.begin() + static_cast<std::ptrdiff_t>(run_end[v]), edges.begin() + static_cast<std::ptrdiff_t>(run_end[v + 1]),
              [](const FaceEdge& x, const FaceEdge& y) { return x.key < y.key || (x.key == y.key && x.face < y.face); });
  return edges;
}

}  // namespace meshprep
