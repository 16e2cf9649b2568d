#include "surface_limits.h"

#include "exact_orientation.h"
#include "worst_tet_maximiser.h"

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
  double angle = 0;                   // radians, summed over the tets at the edge
  std::array<VertexId, 3> face[2]{};  // the two boundary faces at the edge, oriented out of the solid
  VertexId apex[2] = {0, 0};          // their far corners
  int faces = 0;
};

// The tet joining a face oriented out of the solid, (x, y, z), to an inner point: (x, z, y, point).
OneFreeCornerTet on_face(const TetComplex& mesh, const std::array<VertexId, 3>& f) {
  return {{mesh.point(f[0]), mesh.point(f[2]), mesh.point(f[1])}};
}

// With only its smallest dihedral angle counted: the objective with obtuse angles never the worst.
constexpr double kAcuteOnly = 1e300;

// The best smallest dihedral angle of two tets splitting the wedge at edge (u, v): its two boundary
// faces joined to one point X inside it, (face 0, X) and (face 1, X), X placed by the same
// maximiser as the smoothing from two starts inside the wedge (the maximum found, not a proven one).
double best_two_tet_split(const TetComplex& mesh, const BoundaryEdge& edge, VertexId u, VertexId v) {
  const std::vector<OneFreeCornerTet> tets = {on_face(mesh, edge.face[0]), on_face(mesh, edge.face[1])};
  const Vec3 &pu = mesh.point(u), &pv = mesh.point(v);
  const double length = (pv - pu).norm();
  const auto inward = [&](const std::array<VertexId, 3>& f) {
    return -Vec3((mesh.point(f[1]) - mesh.point(f[0])).cross(mesh.point(f[2]) - mesh.point(f[0]))).normalized();
  };
  const Vec3 starts[2] = {0.25 * (pu + pv + mesh.point(edge.apex[0]) + mesh.point(edge.apex[1])),
                          0.5 * (pu + pv) + 0.25 * length * (inward(edge.face[0]) + inward(edge.face[1])).normalized()};
  double best = 0;
  for (const Vec3& start : starts) {
    if (!all_positive(tets, start)) continue;
    const MaximisedPosition at = maximise_worst_tet(tets, start, 0.5 * length, kAcuteOnly);
    best = std::max(best, std::asin(std::clamp(at.worst, 0.0, 1.0)) * 180.0 / M_PI);
  }
  return best;
}

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
        if (edge.faces < 2) edge.face[edge.faces] = f, edge.apex[edge.faces] = f[(e + 2) % 3];
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
    if (edge.faces != 2 || alpha / 3 >= goal_min_dihedral_deg) continue;  // three tets of alpha / 3 may do
    // The forced tet: the first face (x, y, z), oriented outwards, joined to the other apex w is
    // the tet (x, z, y, w), valid if positive.
    const auto& f = edge.face[0];
    const VertexId w = edge.apex[1];
    double forced = 0;
    if (positively_oriented(mesh.point(f[0]), mesh.point(f[2]), mesh.point(f[1]), mesh.point(w)))
      forced = tet_shape(mesh.point(f[0]), mesh.point(f[2]), mesh.point(f[1]), mesh.point(w)).min_dihedral_deg;
    const double bound = std::max({forced, best_two_tet_split(mesh, edge, key.a, key.b), alpha / 3});
    if (bound >= goal_min_dihedral_deg) continue;
    limiting.push_back({key.a, key.b, 0.5 * (mesh.point(key.a) + mesh.point(key.b)), alpha, bound});
  }
  std::sort(limiting.begin(), limiting.end(), [](const LimitingBoundaryEdge& x, const LimitingBoundaryEdge& y) {
    return x.bound_deg != y.bound_deg ? x.bound_deg < y.bound_deg : std::tie(x.a, x.b) < std::tie(y.a, y.b);
  });
  return limiting;
}

}  // namespace meshprep::improve
