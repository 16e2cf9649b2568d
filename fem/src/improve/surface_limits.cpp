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
OneFreeCornerTet on_face(const std::array<Vec3, 3>& f) { return {{f[0], f[2], f[1]}}; }

// With only its smallest dihedral angle counted: the objective with obtuse angles never the worst.
constexpr double kAcuteOnly = 1e300;

// The best smallest dihedral angle of two tets splitting the wedge: its two boundary faces joined
// to one point X inside it, (face 0, X) and (face 1, X), X placed by the same maximiser as the
// smoothing from two starts inside the wedge (the maximum found, not a proven one).
double best_two_tet_split(const BoundaryWedge& w) {
  const std::array<Vec3, 3> faces[2] = {{w.u, w.v, w.apex[0]}, {w.v, w.u, w.apex[1]}};
  const std::vector<OneFreeCornerTet> tets = {on_face(faces[0]), on_face(faces[1])};
  const double length = (w.v - w.u).norm();
  const auto inward = [](const std::array<Vec3, 3>& f) { return -Vec3((f[1] - f[0]).cross(f[2] - f[0])).normalized(); };
  const Vec3 starts[2] = {0.25 * (w.u + w.v + w.apex[0] + w.apex[1]),
                          0.5 * (w.u + w.v) + 0.25 * length * (inward(faces[0]) + inward(faces[1])).normalized()};
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

double interior_angle_deg(const BoundaryWedge& w) {
  const Vec3 axis = (w.v - w.u).normalized();
  const auto across = [&](const Vec3& apex) {
    const Vec3 d = apex - w.u;
    return Vec3(d - d.dot(axis) * axis);
  };
  const Vec3 a0 = across(w.apex[0]), a1 = across(w.apex[1]);
  const double between = std::atan2(a0.cross(a1).norm(), a0.dot(a1)) * 180.0 / M_PI;
  // Convex when apex 1 lies inside, behind face 0 (u, v, apex 0) oriented outwards.
  const bool convex = positively_oriented(w.u, w.apex[0], w.v, w.apex[1]);
  return convex ? between : 360.0 - between;
}

double wedge_bound_deg(const BoundaryWedge& w, double interior_angle_deg, double goal_min_dihedral_deg) {
  if (interior_angle_deg / 3 >= goal_min_dihedral_deg) return interior_angle_deg / 3;  // three tets of alpha / 3 may do
  // The forced tet: face 0 (u, v, apex 0), oriented outwards, joined to apex 1 is the tet
  // (u, apex 0, v, apex 1), valid if positive.
  double forced = 0;
  if (positively_oriented(w.u, w.apex[0], w.v, w.apex[1]))
    forced = tet_shape(w.u, w.apex[0], w.v, w.apex[1]).min_dihedral_deg;
  return std::max({forced, best_two_tet_split(w), interior_angle_deg / 3});
}

double face_bound_deg(const std::array<Vec3, 3>& face, double obtuse_weight) {
  const std::vector<OneFreeCornerTet> tet = {on_face(face)};
  const Vec3 centroid = (face[0] + face[1] + face[2]) / 3.0;
  const Vec3 inward = -Vec3((face[1] - face[0]).cross(face[2] - face[0])).normalized();
  const double size = ((face[1] - face[0]).norm() + (face[2] - face[1]).norm() + (face[0] - face[2]).norm()) / 3;
  double best = 0;
  for (const double height : {0.8 * size, 0.3 * size}) {  // a regular tet's height is 0.82 of its edge
    const Vec3 start = centroid + height * inward;
    if (!all_positive(tet, start)) continue;
    best = std::max(best, maximise_worst_tet(tet, start, 0.5 * size, obtuse_weight).worst);
  }
  return std::asin(std::clamp(best, 0.0, 1.0)) * 180.0 / M_PI;
}

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
    if (edge.faces != 2) continue;
    // The edge as the first face, oriented outwards, runs it: (u, v, apex 0); the second (v, u, apex 1).
    const auto& f = edge.face[0];
    int at = 0;
    while (!((f[at] == key.a || f[at] == key.b) && (f[(at + 1) % 3] == key.a || f[(at + 1) % 3] == key.b))) ++at;
    const BoundaryWedge wedge{mesh.point(f[at]), mesh.point(f[(at + 1) % 3]), {mesh.point(edge.apex[0]), mesh.point(edge.apex[1])}};
    const double bound = wedge_bound_deg(wedge, alpha, goal_min_dihedral_deg);
    if (bound >= goal_min_dihedral_deg) continue;
    limiting.push_back({key.a, key.b, 0.5 * (mesh.point(key.a) + mesh.point(key.b)), alpha, bound});
  }
  std::sort(limiting.begin(), limiting.end(), [](const LimitingBoundaryEdge& x, const LimitingBoundaryEdge& y) {
    return x.bound_deg != y.bound_deg ? x.bound_deg < y.bound_deg : std::tie(x.a, x.b) < std::tie(y.a, y.b);
  });
  return limiting;
}

}  // namespace meshprep::improve
