// Second-order tets (quadratic.h): mid-edge nodes, the boundary's placed on a reference surface
// where every tet around the edge stays valid by its Jacobian's Bezier bound
// (quadratic_jacobian.h).
#include "meshprep/fem/quadratic.h"

#include "quadratic_jacobian.h"

#include "meshprep/core/errors.h"
#include "meshprep/fem/tet_boundary.h"
#include "meshprep/quality/json_values.h"
#include "meshprep/quality/triangle_bvh.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace meshprep {
namespace {

using Clock = std::chrono::steady_clock;

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{a} << 32) | b;
}

// The mesh's edges: each tet edge (6 t + e) grouped by its corners, in the order of the sorted
// corner pairs.
struct Edges {
  std::vector<std::uint64_t> keys;        // per edge, ascending
  std::vector<std::uint32_t> first;       // per edge + 1: its entries in tet_edges
  std::vector<std::uint32_t> tet_edges;   // 6 t + e, grouped by edge

  std::size_t size() const { return keys.size(); }
  std::size_t find(std::uint32_t a, std::uint32_t b) const {
    return static_cast<std::size_t>(std::lower_bound(keys.begin(), keys.end(), edge_key(a, b)) - keys.begin());
  }
};

Edges collect_edges(const TetMesh& mesh) {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> entries;
  entries.reserve(6 * mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (int e = 0; e < 6; ++e)
      entries.emplace_back(edge_key(mesh.tets[t][kTetEdges[e][0]], mesh.tets[t][kTetEdges[e][1]]),
                           static_cast<std::uint32_t>(6 * t + e));
  std::sort(entries.begin(), entries.end());
  Edges edges;
  edges.tet_edges.reserve(entries.size());
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (i == 0 || entries[i].first != entries[i - 1].first) {
      edges.keys.push_back(entries[i].first);
      edges.first.push_back(static_cast<std::uint32_t>(i));
    }
    edges.tet_edges.push_back(entries[i].second);
  }
  edges.first.push_back(static_cast<std::uint32_t>(entries.size()));
  return edges;
}

void check_mesh(const TetMesh& mesh) {
  if (mesh.quadratic()) throw InvalidInput("quadratic: the mesh is already second-order");
  if (mesh.tets.empty()) throw InvalidInput("quadratic: the mesh has no tets");
  // Two ids per edge key in 32 bits each, and 6 entries per tet numbered in 32 bits.
  if (mesh.tets.size() > std::numeric_limits<std::uint32_t>::max() / 6 ||
      mesh.points.size() + 6 * mesh.tets.size() > std::numeric_limits<std::uint32_t>::max())
    throw InvalidInput("quadratic: too many tets for 32-bit point indices");
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (const std::uint32_t v : mesh.tets[t])
      if (v >= mesh.points.size())
        throw InvalidInput("quadratic: tet " + std::to_string(t) + " references point " + std::to_string(v) + " of " +
                           std::to_string(mesh.points.size()));
}

// Whether every tet of edge `edge` is valid with the nodes as they are: its Jacobian's Bezier
// bound at least kMinJacobianRatio times its straight det J (which must be positive).
bool tets_valid(const TetMesh& mesh, const Edges& edges, std::size_t edge) {
  for (std::uint32_t i = edges.first[edge]; i < edges.first[edge + 1]; ++i) {
    const std::array<Vec3, 10> x = detail::tet_nodes(mesh, edges.tet_edges[i] / 6);
    const double straight = detail::straight_jacobian(x);
    if (!(straight > 0 && detail::jacobian_lower_bound(x) >= kMinJacobianRatio * straight)) return false;
  }
  return true;
}

// The reference point for each boundary edge's node (its midpoint's closest point), found in
// parallel; a point the mutual-closest rule refuses is marked by a NaN distance.
struct Placement {
  Vec3 point = Vec3::Zero();
  double distance = 0;
  bool on_reference = false;  ///< the midpoint is on the reference already (kOnReference)
};

std::vector<Placement> reference_points(const TetMesh& mesh, const Edges& edges, const std::vector<std::size_t>& boundary,
                                        const TriangleSoup& reference, const std::vector<Triangle>& faces) {
  const TriangleBvh to_reference(reference);
  TriangleSoup own;  // the linear boundary, on its own copy of the corners
  own.points.assign(mesh.points.begin(), mesh.points.begin() + static_cast<std::ptrdiff_t>(mesh.points.size()));
  own.triangles = faces;
  const TriangleBvh to_own(own);
  std::vector<Placement> placements(boundary.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, boundary.size(), 256), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const std::uint64_t key = edges.keys[boundary[i]];
      const Vec3 a = mesh.points[key >> 32], b = mesh.points[key & 0xffffffffu];
      const Vec3 mid = 0.5 * (a + b);
      const TriangleBvh::Hit hit = to_reference.closest_point(mid);
      Placement& p = placements[i];
      p.point = hit.point;
      p.distance = std::sqrt(hit.squared_distance);
      p.on_reference = p.distance <= kOnReference * (b - a).norm();
      // The boundary must not pass nearer the reference point than kMutualClosest x the move.
      const double limit = kMutualClosest * p.distance;
      if (!p.on_reference && to_own.reaches_within(hit.point, limit * limit * (1 - 1e-12)))
        p.distance = std::numeric_limits<double>::quiet_NaN();
    }
  });
  return placements;
}

}  // namespace

QuadraticResult make_quadratic(TetMesh& mesh, const TriangleSoup* reference) {
  const Clock::time_point start = Clock::now();
  check_mesh(mesh);
  QuadraticResult result;
  const Edges edges = collect_edges(mesh);
  result.edges = edges.size();
  const std::size_t corner_points = mesh.points.size();

  // A straight node on every edge.
  mesh.points.reserve(corner_points + edges.size());
  mesh.tet_edge_nodes.assign(mesh.tets.size(), TetEdgeNodes{});
  for (std::size_t edge = 0; edge < edges.size(); ++edge) {
    const auto node = static_cast<std::uint32_t>(corner_points + edge);
    const std::uint64_t key = edges.keys[edge];
    mesh.points.push_back(0.5 * (mesh.points[key >> 32] + mesh.points[key & 0xffffffffu]));
    for (std::uint32_t i = edges.first[edge]; i < edges.first[edge + 1]; ++i)
      mesh.tet_edge_nodes[edges.tet_edges[i] / 6][edges.tet_edges[i] % 6] = node;
  }

  // The boundary edges, ascending.
  const std::vector<Triangle> faces = tet_boundary(mesh);
  std::vector<std::size_t> boundary;
  boundary.reserve(3 * faces.size() / 2);
  for (const Triangle& f : faces)
    for (int k = 0; k < 3; ++k) boundary.push_back(edges.find(f[k], f[(k + 1) % 3]));
  std::sort(boundary.begin(), boundary.end());
  boundary.erase(std::unique(boundary.begin(), boundary.end()), boundary.end());
  result.boundary_edges = boundary.size();

  // Each boundary node onto the reference, one edge after the other (each judged with the nodes
  // placed before it), kept only where its tets stay valid.
  if (reference && !reference->triangles.empty()) {
    const std::vector<Placement> placements = reference_points(mesh, edges, boundary, *reference, faces);
    for (std::size_t i = 0; i < boundary.size(); ++i) {
      const std::size_t edge = boundary[i];
      const Placement& p = placements[i];
      if (p.on_reference) {
        ++result.on_reference;
        continue;
      }
      if (std::isnan(p.distance)) {
        ++result.straight_off_reference;
        continue;
      }
      Vec3& node = mesh.points[corner_points + edge];
      const Vec3 straight = node;
      node = p.point;
      if (!tets_valid(mesh, edges, edge)) {
        node = straight;
        ++result.straight_inverting;
        continue;
      }
      ++result.curved_edges;
      const std::uint64_t key = edges.keys[edge];
      const double length = (mesh.points[key >> 32] - mesh.points[key & 0xffffffffu]).norm();
      if (length > 0) result.max_offset_relative = std::max(result.max_offset_relative, p.distance / length);
    }
  }

  if (result.straight_inverting > 0)
    result.taken_back.push_back(
        {"second_order", "positive Jacobian", "curved boundary edges", result.straight_inverting,
         "placing their mid-edge node on the reference would fold a tet (the Bezier bound of det J); they are kept "
         "straight",
         {{"curved_edges", static_cast<double>(result.curved_edges + result.straight_inverting)}},
         {{"curved_edges", static_cast<double>(result.curved_edges)}}});
  result.min_scaled_jacobian = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const std::array<Vec3, 10> x = detail::tet_nodes(mesh, t);
    result.min_scaled_jacobian = std::min(result.min_scaled_jacobian, detail::nodal_jacobian(x).min_scaled);
    if (!(detail::jacobian_lower_bound(x) > 0)) ++result.nonpositive_jacobian_tets;
  }
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

TriangleSoup quadratic_boundary(const TetMesh& mesh, int subdivisions) {
  if (subdivisions < 1) throw InvalidInput("quadratic_boundary: subdivisions must be >= 1");
  const std::vector<Triangle> faces = tet_boundary(mesh);
  TetMesh with_faces;  // the boundary's own mid-nodes, looked up through boundary_face_edge_nodes
  with_faces.tets = mesh.tets;
  with_faces.tet_edge_nodes = mesh.tet_edge_nodes;
  with_faces.boundary_faces = faces;
  const std::vector<std::array<std::uint32_t, 3>> mids = boundary_face_edge_nodes(with_faces);
  const int n = subdivisions;
  const auto lattice = [n](int i, int j) { return static_cast<std::uint32_t>(i * (n + 1) - i * (i - 1) / 2 + j); };
  const std::size_t per_face = static_cast<std::size_t>((n + 1) * (n + 2) / 2);
  TriangleSoup soup;
  soup.points.reserve(faces.size() * per_face);
  soup.triangles.reserve(faces.size() * static_cast<std::size_t>(n * n));
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Vec3 &a = mesh.points[faces[f][0]], &b = mesh.points[faces[f][1]], &c = mesh.points[faces[f][2]];
    // The 6-node triangle's map: sum_i l_i (2 l_i - 1) x_i + 4 l_0 l_1 m_01 + 4 l_1 l_2 m_12 + 4 l_2 l_0 m_20.
    const Vec3 ab = mids.empty() ? Vec3(0.5 * (a + b)) : mesh.points[mids[f][0]];
    const Vec3 bc = mids.empty() ? Vec3(0.5 * (b + c)) : mesh.points[mids[f][1]];
    const Vec3 ca = mids.empty() ? Vec3(0.5 * (c + a)) : mesh.points[mids[f][2]];
    const auto first = static_cast<std::uint32_t>(soup.points.size());
    for (int i = 0; i <= n; ++i)      // l_1 = i / n
      for (int j = 0; j <= n - i; ++j) {  // l_2 = j / n
        const double l1 = static_cast<double>(i) / n, l2 = static_cast<double>(j) / n, l0 = 1 - l1 - l2;
        soup.points.push_back(l0 * (2 * l0 - 1) * a + l1 * (2 * l1 - 1) * b + l2 * (2 * l2 - 1) * c + 4 * l0 * l1 * ab +
                              4 * l1 * l2 * bc + 4 * l2 * l0 * ca);
      }
    // Lattice row i holds n + 1 - i points; both triangle kinds keep the face's orientation
    // (l_1 grows towards b, l_2 towards c: (i, j), (i + 1, j), (i, j + 1) runs a -> b -> c).
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n - i; ++j) {
        soup.triangles.push_back({first + lattice(i, j), first + lattice(i + 1, j), first + lattice(i, j + 1)});
        if (j + 1 < n - i)
          soup.triangles.push_back({first + lattice(i + 1, j), first + lattice(i + 1, j + 1), first + lattice(i, j + 1)});
      }
  }
  return soup;
}

nlohmann::ordered_json to_json(const QuadraticResult& r) {
  return {{"edges", r.edges},
          {"boundary_edges", r.boundary_edges},
          {"curved_edges", r.curved_edges},
          {"on_reference", r.on_reference},
          {"straight_inverting", r.straight_inverting},
          {"straight_off_reference", r.straight_off_reference},
          {"max_offset_relative", r.max_offset_relative},
          {"min_scaled_jacobian", r.min_scaled_jacobian},
          {"nonpositive_jacobian_tets", r.nonpositive_jacobian_tets},
          {kGuardsTakenBackKey, json_taken_back(r.taken_back)},
          {"seconds", r.seconds}};
}

}  // namespace meshprep
