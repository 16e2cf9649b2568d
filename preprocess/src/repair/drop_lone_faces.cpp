#include "repair/drop_lone_faces.h"

#include <cstdint>

namespace meshprep::detail {

std::size_t drop_lone_faces(TriangleSoup& soup, const std::vector<FaceEdge>& uses) {
  std::vector<int> shared_edges(soup.triangles.size(), 0);
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i > 1)
      for (std::size_t k = i; k < j; ++k) ++shared_edges[uses[k].face];
    i = j;
  }
  std::size_t lone = 0;
  for (const int shared : shared_edges) lone += shared == 0;
  if (lone == 0 || lone == soup.triangles.size()) return 0;
  std::size_t kept = 0;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    if (shared_edges[f] == 0) continue;
    soup.triangles[kept] = soup.triangles[f];
    if (!soup.patches.empty()) soup.patches[kept] = soup.patches[f];
    ++kept;
  }
  soup.triangles.resize(kept);
  if (!soup.patches.empty()) soup.patches.resize(kept);
  // Their corners no kept face uses go too, the others keep their order.
  std::vector<std::uint32_t> renumber(soup.points.size(), UINT32_MAX);
  for (const Triangle& t : soup.triangles)
    for (const std::uint32_t v : t) renumber[v] = 0;
  std::size_t used = 0;
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    if (renumber[v] != UINT32_MAX) {
      renumber[v] = static_cast<std::uint32_t>(used);
      soup.points[used++] = soup.points[v];
    }
  soup.points.resize(used);
  for (Triangle& t : soup.triangles)
    for (std::uint32_t& v : t) v = renumber[v];
  return lone;
}

}  // namespace meshprep::detail
