#include "topological_moves.h"

#include <algorithm>
#include <limits>

namespace meshprep::improve {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

int corner_of(const Tetrahedron& t, VertexId v) {
  for (int c = 0; c < 4; ++c)
    if (t[c] == v) return c;
  return -1;
}

VertexId fourth_corner(const Tetrahedron& t, VertexId a, VertexId b, VertexId c) {
  return t[0] + t[1] + t[2] + t[3] - a - b - c;  // unsigned wrap-around is exact
}

}  // namespace

Move edge_removal(const TetComplex& mesh, TetId t, VertexId a, VertexId b, std::size_t max_ring) {
  Move move;
  std::vector<VertexId> ring;
  if (!mesh.edge_ring(t, a, b, max_ring, move.old, ring)) return Move{};
  const std::size_t n = ring.size();
  move.old_worst = kInfinity;
  for (const TetId old : move.old) move.old_worst = std::min(move.old_worst, mesh.quality(old));

  // Klincsek's dynamic programme: best[i][j] is the largest worst quality of a triangulation of
  // the sub-polygon ring[i..j] (closed by the chord i-j); each of its triangles (i, k, j) makes
  // the tets (a, ri, rk, rj) and (b, ri, rj, rk).
  const Vec3 &pa = mesh.point(a), &pb = mesh.point(b);
  std::vector<double> best(n * n, kInfinity);
  std::vector<std::size_t> split(n * n, 0);
  for (std::size_t span = 2; span < n; ++span)
    for (std::size_t i = 0; i + span < n; ++i) {
      const std::size_t j = i + span;
      double value = -kInfinity;
      for (std::size_t k = i + 1; k < j; ++k) {
        const double sides = std::min(best[i * n + k], best[k * n + j]);
        if (sides <= value) continue;
        const Vec3 &ri = mesh.point(ring[i]), &rk = mesh.point(ring[k]), &rj = mesh.point(ring[j]);
        const double triangle = std::min(mesh.quality_of(pa, ri, rk, rj), mesh.quality_of(pb, ri, rj, rk));
        const double worst = std::min(sides, triangle);
        if (worst > value) value = worst, split[i * n + j] = k;
      }
      best[i * n + j] = value;
    }
  move.new_worst = best[n - 1];
  std::vector<std::pair<std::size_t, std::size_t>> pending = {{0, n - 1}};
  while (!pending.empty()) {
    const auto [i, j] = pending.back();
    pending.pop_back();
    if (j < i + 2) continue;
    const std::size_t k = split[i * n + j];
    move.fresh.push_back({a, ring[i], ring[k], ring[j]});
    move.fresh.push_back({b, ring[i], ring[j], ring[k]});
    pending.push_back({i, k});
    pending.push_back({k, j});
  }
  return move;
}

namespace {

// One face of the tree of faces sandwiched between a and b: (x, y, z) with its normal towards b,
// the tets (a, face) and (b, face), and per edge (x,y), (y,z), (z,x) the quality of the tet
// (a, b, edge) that the edge makes if it stays on the boundary of the removed faces, and the
// child face across it, if any.
struct SandwichedFace {
  std::array<VertexId, 3> face;
  TetId below, above;  // apex a, apex b
  std::array<double, 3> stop{};
  std::array<int, 3> child{-1, -1, -1};
  std::array<bool, 3> expand{false, false, false};
  double value = 0;
};

}  // namespace

Move multi_face_removal(const TetComplex& mesh, TetId t, int corner, std::size_t max_faces) {
  if (mesh.constrained(t, corner)) return Move{};
  const TetId u = mesh.neighbour(t, corner);
  const Tetrahedron& below = mesh.tet(t);
  const VertexId a = below[corner];
  const std::array<VertexId, 3> first = outward_face(below, corner);  // normal away from a
  const VertexId b = fourth_corner(mesh.tet(u), first[0], first[1], first[2]);
  const Vec3 &pa = mesh.point(a), &pb = mesh.point(b);

  std::vector<SandwichedFace> faces;
  faces.push_back({first, t, u});
  // Grow the tree breadth-first: across edge e = (x, y) of face (x, y, z) the tets (a, x, y, z)
  // and (b, x, y, z) have neighbours across (a, x, y) and (b, x, y); when both have the same
  // fourth corner z', the face (y, x, z') is sandwiched too.
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (int e = 0; e < 3; ++e) {
      const VertexId x = faces[f].face[e], y = faces[f].face[(e + 1) % 3], z = faces[f].face[(e + 2) % 3];
      faces[f].stop[e] = mesh.quality_of(pa, pb, mesh.point(x), mesh.point(y));
      if (f > 0 && e == 0) continue;  // the edge shared with the parent
      if (faces.size() >= max_faces) continue;
      const TetId under = faces[f].below, over = faces[f].above;
      const int c_under = corner_of(mesh.tet(under), z), c_over = corner_of(mesh.tet(over), z);
      if (mesh.constrained(under, c_under) || mesh.constrained(over, c_over)) continue;
      const TetId next_under = mesh.neighbour(under, c_under), next_over = mesh.neighbour(over, c_over);
      const VertexId apex = fourth_corner(mesh.tet(next_under), a, x, y);
      if (apex != fourth_corner(mesh.tet(next_over), b, x, y) || apex == a || apex == b) continue;
      bool seen = false;
      for (const SandwichedFace& s : faces) seen = seen || s.below == next_under;
      if (seen || mesh.constrained(next_under, corner_of(mesh.tet(next_under), a))) continue;
      faces[f].child[e] = static_cast<int>(faces.size());
      faces.push_back({{y, x, apex}, next_under, next_over});  // edge 0 = (y, x): shared with the parent
    }
  }
  // Bottom-up (children come after parents): on each edge keep the stop or the child's subtree,
  // whichever has the better worst tet.
  for (std::size_t f = faces.size(); f-- > 0;) {
    SandwichedFace& s = faces[f];
    s.value = kInfinity;
    for (int e = (f > 0 ? 1 : 0); e < 3; ++e) {
      double chosen = s.stop[e];
      if (s.child[e] >= 0 && faces[s.child[e]].value > chosen) {
        chosen = faces[s.child[e]].value;
        s.expand[e] = true;
      }
      s.value = std::min(s.value, chosen);
    }
  }
  Move move;
  move.new_worst = faces[0].value;
  move.old_worst = kInfinity;
  std::vector<int> chosen = {0};
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    const SandwichedFace& s = faces[chosen[k]];
    move.old.push_back(s.below);
    move.old.push_back(s.above);
    move.old_worst = std::min({move.old_worst, mesh.quality(s.below), mesh.quality(s.above)});
    for (int e = (chosen[k] > 0 ? 1 : 0); e < 3; ++e) {
      if (s.expand[e]) {
        chosen.push_back(s.child[e]);
        continue;
      }
      move.fresh.push_back({a, b, s.face[e], s.face[(e + 1) % 3]});
    }
  }
  return move;
}

}  // namespace meshprep::improve
