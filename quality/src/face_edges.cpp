#include "meshprep/quality/face_edges.h"

#include "meshprep/core/bucket_sort.h"

namespace meshprep {

// Ordered by key, whose high half is the smaller vertex: sorted by that vertex's runs
// (bucket_sort.h), which costs a third of one comparison sort of all 3 x faces edges, and those
// are most of what a clean surface costs topology and repair.
std::vector<FaceEdge> sorted_face_edges(const SoupView& soup) {
  std::vector<FaceEdge> edges;
  edges.reserve(3 * soup.triangles.size());
  for (std::uint32_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t a = t[c], b = t[(c + 1) % 3];
      edges.push_back({edge_key(a, b), f, a < b});
    }
  }
  sort_by_buckets(
      edges, [](const FaceEdge& e) { return e.lo(); },
      [](const FaceEdge& x, const FaceEdge& y) { return x.key < y.key || (x.key == y.key && x.face < y.face); });
  return edges;
}

}  // namespace meshprep
