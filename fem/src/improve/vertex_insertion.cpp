#include "vertex_insertion.h"

#include "worst_tet_maximiser.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace meshprep::improve {
namespace {

// A step of the new vertex's placement never goes further than this share of the seed tet's
// mean edge.
constexpr double kMaxStepOfMeanEdge = 0.5;
// The growth gives up after this many tets without a better cavity.
constexpr std::size_t kPatience = 10;

struct CavityFace {
  std::array<VertexId, 3> face;  // oriented out of the cavity
  TetId inside;                  // the cavity tet it belongs to
  int corner;                    // ... opposite this corner
};

bool same_face(const std::array<VertexId, 3>& f, const std::array<VertexId, 3>& g) {
  return (f[0] == g[0] || f[0] == g[1] || f[0] == g[2]) && (f[1] == g[0] || f[1] == g[1] || f[1] == g[2]) &&
         (f[2] == g[0] || f[2] == g[1] || f[2] == g[2]);
}

// The outward face (x, y, z) joined to the new vertex: the tet (x, z, y, new), positive when
// the new vertex is on the face's inner side.
OneFreeCornerTet joined(const TetComplex& mesh, const CavityFace& f) {
  return {{mesh.point(f.face[0]), mesh.point(f.face[2]), mesh.point(f.face[1])}};
}

double mean_edge(const TetComplex& mesh, const Tetrahedron& t) {
  double sum = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) sum += (mesh.point(t[i]) - mesh.point(t[j])).norm();
  return sum / 6;
}

}  // namespace

bool insert_vertex(TetComplex& mesh, TetId t, std::size_t max_cavity) {
  const Tetrahedron& seed = mesh.tet(t);
  const double weight = mesh.obtuse_weight();
  const double max_step = kMaxStepOfMeanEdge * mean_edge(mesh, seed);
  Vec3 p = 0.25 * (mesh.point(seed[0]) + mesh.point(seed[1]) + mesh.point(seed[2]) + mesh.point(seed[3]));
  std::vector<TetId> cavity = {t};
  std::vector<CavityFace> faces;
  for (int c = 0; c < 4; ++c) faces.push_back({outward_face(seed, c), t, c});
  double old_worst = mesh.quality(t);
  double best_value = -std::numeric_limits<double>::infinity();
  std::size_t best_size = 0;
  Vec3 best_position = p;
  std::vector<OneFreeCornerTet> tets;
  while (true) {
    tets.clear();
    for (const CavityFace& f : faces) tets.push_back(joined(mesh, f));
    const MaximisedPosition placed = maximise_worst_tet(tets, p, max_step, weight);
    p = placed.position;
    if (placed.worst > old_worst && placed.worst > best_value)
      best_value = placed.worst, best_size = cavity.size(), best_position = p;
    if (cavity.size() >= max_cavity || cavity.size() >= best_size + kPatience) break;
    // Grow across the worst face that can be removed.
    std::size_t grow = faces.size();
    double grow_quality = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < faces.size(); ++k) {
      if (mesh.constrained(faces[k].inside, faces[k].corner)) continue;
      const double q = worst_quality({tets[k]}, p, weight);
      if (q < grow_quality) grow = k, grow_quality = q;
    }
    if (grow == faces.size()) break;
    const TetId next = mesh.neighbour(faces[grow].inside, faces[grow].corner);
    cavity.push_back(next);
    old_worst = std::min(old_worst, mesh.quality(next));
    for (int c = 0; c < 4; ++c) {
      const auto f = outward_face(mesh.tet(next), c);
      const auto shared = std::find_if(faces.begin(), faces.end(), [&](const CavityFace& g) { return same_face(f, g.face); });
      if (shared != faces.end()) faces.erase(shared);  // now inside the cavity (the face crossed, at least)
      else faces.push_back({f, next, c});
    }
  }
  if (best_size == 0) return false;
  cavity.resize(best_size);
  const VertexId v = mesh.add_point(best_position);
  std::vector<Tetrahedron> fresh;
  for (const TetId c : cavity)
    for (int k = 0; k < 4; ++k) {
      const TetId n = mesh.neighbour(c, k);
      if (n != kNoTet && std::find(cavity.begin(), cavity.end(), n) != cavity.end()) continue;
      const auto f = outward_face(mesh.tet(c), k);
      fresh.push_back({f[0], f[2], f[1], v});
    }
  if (!mesh.replace(cavity, fresh)) {
    mesh.discard_point(v);
    return false;
  }
  return true;
}

}  // namespace meshprep::improve
