#include "compound_move.h"

#include "vertex_smoothing.h"

#include <algorithm>
#include <cassert>
#include <limits>

namespace meshprep::improve {
namespace {

double worst_of(const TetComplex& mesh, const std::vector<TetId>& tets) {
  double worst = std::numeric_limits<double>::infinity();
  for (const TetId t : tets) worst = std::min(worst, mesh.quality(t));
  return worst;
}

}  // namespace

bool move_and_smooth(TetComplex& mesh, const Move& move, std::vector<TetId>& changed) {
  std::vector<VertexId> corners;
  for (const Tetrahedron& t : move.fresh)
    for (const VertexId v : t)
      if (mesh.free_vertex(v) && std::find(corners.begin(), corners.end(), v) == corners.end()) corners.push_back(v);
  if (corners.empty()) return false;  // nothing would move: the plain move already said no

  // Everything whose shape may change: the replaced tets and the corners' tets.
  std::vector<TetId> star, before = move.old;
  std::vector<Vec3> positions;
  for (const VertexId v : corners) {
    positions.push_back(mesh.point(v));
    mesh.star(v, star);
    before.insert(before.end(), star.begin(), star.end());
  }
  const double worst_before = worst_of(mesh, before);
  std::vector<Tetrahedron> old_tets;
  for (const TetId t : move.old) old_tets.push_back(mesh.tet(t));

  if (!mesh.replace(move.old, move.fresh)) return false;
  const std::vector<TetId> created = mesh.created();
  for (const VertexId v : corners) smooth_vertex(mesh, v);
  changed = created;
  for (const VertexId v : corners) {
    mesh.star(v, star);
    changed.insert(changed.end(), star.begin(), star.end());
  }
  std::sort(changed.begin(), changed.end());
  changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
  if (worst_of(mesh, changed) > worst_before) return true;

  // Undo: the points back to their bits, which makes the old tets valid again, then the tets.
  for (std::size_t k = 0; k < corners.size(); ++k) {
    mesh.star(corners[k], star);
    mesh.move_point(corners[k], positions[k], star);
  }
  [[maybe_unused]] const bool restored = mesh.replace(created, old_tets, &move.old);
  assert(restored);
  return false;
}

}  // namespace meshprep::improve
