#include "edge_contraction.h"

#include <algorithm>
#include <limits>

namespace meshprep::improve {

Move best_contraction(const TetComplex& mesh, VertexId u) {
  Move best;
  std::vector<TetId> star;
  mesh.star(u, star);
  if (star.empty()) return best;
  std::vector<VertexId> neighbours;
  double old_worst = std::numeric_limits<double>::infinity();
  for (const TetId t : star) {
    old_worst = std::min(old_worst, mesh.quality(t));
    for (const VertexId v : mesh.tet(t))
      if (v != u && std::find(neighbours.begin(), neighbours.end(), v) == neighbours.end()) neighbours.push_back(v);
  }
  double best_worst = -std::numeric_limits<double>::infinity();
  VertexId best_target = u;
  for (const VertexId w : neighbours) {
    double worst = std::numeric_limits<double>::infinity();
    for (const TetId t : star) {
      Tetrahedron c = mesh.tet(t);
      if (std::find(c.begin(), c.end(), w) != c.end()) continue;  // has the edge uw: disappears
      std::replace(c.begin(), c.end(), u, w);
      worst = std::min(worst, mesh.quality_of(c));
      if (worst <= best_worst) break;
    }
    if (worst > best_worst) best_worst = worst, best_target = w;
  }
  if (best_target == u) return best;
  best.old = star;
  best.old_worst = old_worst;
  best.new_worst = best_worst;
  for (const TetId t : star) {
    Tetrahedron c = mesh.tet(t);
    if (std::find(c.begin(), c.end(), best_target) != c.end()) continue;
    std::replace(c.begin(), c.end(), u, best_target);
    best.fresh.push_back(c);
  }
  return best;
}

}  // namespace meshprep::improve
