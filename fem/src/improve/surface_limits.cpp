#include "surface_limits.h"

#include "exact_orientation.h"

#include "meshprep/fem/tet_quality.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace meshprep::improve {
namespace {

struct EdgeKey {
  VertexId a, b;  // a < b
  int region;
  bool operator==(const EdgeKey& o) const { return a == o.a && b == o.b && region == o.region; }
};
struct EdgeKeyHash {
  std::size_t operator()(const EdgeKey& k) const {
    std::uint64_t h = (std::uint64_t(k.a) << 32 | k.b) * 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(h ^ (h >> 31) ^ static_cast<std::uint64_t>(k.region));
  }
};
EdgeKey edge_key(VertexId a, VertexId b, int region) { return a < b ? EdgeKey{a, b, region} : EdgeKey{b, a, region}; }

struct BoundaryEdge {
  double angle = 0;          // radians, summed over the tets at the edge
  VertexId apex[2] = {0, 0};  // the far corners of the boundary faces at the edge
  std::array<VertexId, 3> face{};  // the first boundary face, oriented out of the solid
  int faces = 0;
};

// The dihedral angle of a tet at its edge (corners i, j): pi minus the angle between the outward
// normals of the faces opposite the other two corners.
double dihedral_at(const TetComplex& mesh, const Tetrahedron& t, int i, int j) {
  int other[2], k = 0;
  for (int c = 0; c < 4; ++c)
    if (c != i && c != j) other[k++] = c;
  auto normal = [&](int opposite) {
    const auto f = outward_face(t, opposite);
    return Vec3((mesh.point(f[1]) - mesh.point(f[0])).cross(mesh.point(f[2]) - mesh.point(f[0])));
  };
  const Vec3 n0 = normal(other[0]), n1 = normal(other[1]);
  return M_PI - std::atan2(n0.cross(n1).norm(), n0.dot(n1));
}

}  // namespace

std::vector<LimitingBoundaryEdge> limiting_boundary_edges(const TetComplex& mesh, double goal_min_dihedral_deg) {
  std::unordered_map<EdgeKey, BoundaryEdge, EdgeKeyHash> edges;
  for (TetId t = 0; t < mesh.tet_slots(); ++t) {
    if (!mesh.alive(t)) continue;
    for (int c = 0; c < 4; ++c) {
      if (!mesh.constrained(t, c)) continue;
      const auto f = outward_face(mesh.tet(t), c);
      for (int e = 0; e < 3; ++e) {
        BoundaryEdge& edge = edges[edge_key(f[e], f[(e + 1) % 3], mesh.region(t))];
        if (edge.faces < 2) edge.apex[edge.faces] = f[(e + 2) % 3];
        if (edge.faces == 0) edge.face = f;
        ++edge.faces;
      }
    }
  }
  for (TetId t = 0; t < mesh.tet_slots(); ++t) {
    if (!mesh.alive(t)) continue;
    const Tetrahedron& tet = mesh.tet(t);
    if (mesh.free_vertex(tet[0]) + mesh.free_vertex(tet[1]) + mesh.free_vertex(tet[2]) + mesh.free_vertex(tet[3]) > 2)
      continue;  // no edge with both ends on constrained faces
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const auto found = edges.find(edge_key(tet[i], tet[j], mesh.region(t)));
        if (found != edges.end()) found->second.angle += dihedral_at(mesh, tet, i, j);
      }
  }
  std::vector<LimitingBoundaryEdge> limiting;
  for (const auto& [key, edge] : edges) {
    const double alpha = edge.angle * 180.0 / M_PI;
    if (edge.faces != 2 || alpha >= 2 * goal_min_dihedral_deg) continue;  // alpha / 2 already allows the goal
    // The forced tet: the first face (x, y, z), oriented outwards, joined to the other apex w is
    // the tet (x, z, y, w), valid if positive.
    const auto& f = edge.face;
    const VertexId w = edge.apex[1];
    double forced = 0;
    if (positively_oriented(mesh.point(f[0]), mesh.point(f[2]), mesh.point(f[1]), mesh.point(w)))
      forced = tet_shape(mesh.point(f[0]), mesh.point(f[2]), mesh.point(f[1]), mesh.point(w)).min_dihedral_deg;
    const double bound = std::max(forced, alpha / 2);
    if (bound >= goal_min_dihedral_deg) continue;
    limiting.push_back({key.a, key.b, 0.5 * (mesh.point(key.a) + mesh.point(key.b)), alpha, bound});
  }
  std::sort(limiting.begin(), limiting.end(), [](const LimitingBoundaryEdge& x, const LimitingBoundaryEdge& y) {
    return x.bound_deg != y.bound_deg ? x.bound_deg < y.bound_deg : std::tie(x.a, x.b) < std::tie(y.a, y.b);
  });
  return limiting;
}

}  // namespace meshprep::improve
