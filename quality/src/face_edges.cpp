#include "meshprep/quality/face_edges.h"

#include <algorithm>

namespace meshprep {

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
  std::sort(edges.begin(), edges.end(),
            [](const FaceEdge& x, const FaceEdge& y) { return x.key < y.key || (x.key == y.key && x.face < y.face); });
  return edges;
}

}  // namespace meshprep
