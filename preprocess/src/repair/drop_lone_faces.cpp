#include "repair/drop_lone_faces.h"

#include "repair/weld_vertices.h"

#include <algorithm>

namespace meshprep::detail {

std::size_t drop_lone_faces(TriangleSoup& soup, const std::vector<FaceEdge>& uses) {
  std::vector<char> lone(soup.triangles.size(), 1);
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i > 1)
      for (std::size_t k = i; k < j; ++k) lone[uses[k].face] = 0;
    i = j;
  }
  const auto count = static_cast<std::size_t>(std::count(lone.begin(), lone.end(), 1));
  if (count == 0 || count == soup.triangles.size()) return 0;
  remove_faces(soup, lone);
  drop_unused_vertices(soup);  // their corners no kept face uses
  return count;
}

}  // namespace meshprep::detail
