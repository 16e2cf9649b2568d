#include "shared/intersection_guard.h"

#include "meshprep/core/soup_view.h"
#include "meshprep/quality/self_intersections.h"

namespace meshprep::detail {

std::size_t undo_new_intersections(TriMesh& mesh, const std::vector<TriMesh::Point>& before, std::size_t allowed) {
  return undo_new_intersections(mesh, before, [allowed] { return allowed; });
}

std::size_t undo_new_intersections(TriMesh& mesh, const std::vector<TriMesh::Point>& before,
                                   const std::function<std::size_t()>& allowed) {
  std::size_t undone = 0;
  for (int round = 0; round < 8; ++round) {
    const MeshSoupView surface(mesh);  // (its points are the mesh's: they move below, after the search)
    const SelfIntersections found = find_self_intersections(surface);
    if (found.count == 0 || found.count <= allowed()) break;
    for (const auto& [a, b] : found.pairs)
      for (const std::size_t f : {a, b})
        for (const std::uint32_t v : surface.triangles()[f]) {
          const TriMesh::VertexHandle handle(static_cast<int>(v));
          if (mesh.point(handle) == before[v]) continue;
          mesh.set_point(handle, before[v]);
          ++undone;
        }
  }
  return undone;
}

}  // namespace meshprep::detail
