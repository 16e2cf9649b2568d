// Creases of a surface: runs of sharp edges (creases.h).
#include "shared/creases.h"

#include "shared/edge_lengths.h"
#include "shared/triangle_angles.h"

#include "meshprep/core/union_find.h"

#include <cmath>

namespace meshprep::detail {

using VertexHandle = TriMesh::VertexHandle;
using EdgeHandle = TriMesh::EdgeHandle;

namespace {

constexpr double kShortestCrease = 5;  // median edge lengths

Vec3 point(const TriMesh& mesh, VertexHandle v) { return to_eigen(mesh.point(v)); }

bool sharp(const TriMesh& mesh, EdgeHandle e, double cos_feature) {
  const Vec3 n0 = to_eigen(mesh.calc_face_normal(mesh.face_handle(mesh.halfedge_handle(e, 0))));
  const Vec3 n1 = to_eigen(mesh.calc_face_normal(mesh.face_handle(mesh.halfedge_handle(e, 1))));
  const double norms = n0.norm() * n1.norm();
  return norms > 0 && n0.dot(n1) < cos_feature * norms;
}

}  // namespace

VertexHandle other_end(const TriMesh& mesh, EdgeHandle e, VertexHandle v) {
  const VertexHandle a = mesh.to_vertex_handle(mesh.halfedge_handle(e, 0));
  return a == v ? mesh.to_vertex_handle(mesh.halfedge_handle(e, 1)) : a;
}

std::vector<std::vector<EdgeHandle>> incident(const TriMesh& mesh, const std::vector<char>& feature) {
  std::vector<std::vector<EdgeHandle>> edges(mesh.n_vertices());
  for (const auto e : mesh.edges())
    if (feature[static_cast<std::size_t>(e.idx())])
      for (int i : {0, 1}) edges[static_cast<std::size_t>(mesh.to_vertex_handle(mesh.halfedge_handle(e, i)).idx())].push_back(e);
  return edges;
}

bool straight_through(const TriMesh& mesh, VertexHandle v, const std::vector<EdgeHandle>& edges, double cosine) {
  if (edges.size() != 2) return false;
  const Vec3 x = point(mesh, v);
  const Vec3 a = point(mesh, other_end(mesh, edges[0], v)) - x, b = point(mesh, other_end(mesh, edges[1], v)) - x;
  return a.dot(b) <= cosine * a.norm() * b.norm();
}

namespace {

// Whether face f has a neighbour in its plane (within kCoplanarCosine) across one of its edges.
bool has_coplanar_neighbour(const TriMesh& mesh, TriMesh::FaceHandle f) {
  const Vec3 n = to_eigen(mesh.calc_face_normal(f));
  for (const auto h : mesh.fh_range(f)) {
    const auto g = mesh.opposite_face_handle(h);
    if (g.is_valid() && n.dot(to_eigen(mesh.calc_face_normal(g))) > kCoplanarCosine) return true;
  }
  return false;
}

}  // namespace

std::vector<char> creases(const TriMesh& mesh, double cos_feature, bool between_planes) {
  std::vector<char> candidate(mesh.n_edges(), 0);
  for (const auto e : mesh.edges())
    if (!mesh.is_boundary(e) && sharp(mesh, e, cos_feature)) candidate[static_cast<std::size_t>(e.idx())] = 1;
  const auto edges_of = incident(mesh, candidate);
  UnionFind runs(mesh.n_edges());
  for (const auto v : mesh.vertices()) {
    const auto& edges = edges_of[static_cast<std::size_t>(v.idx())];
    if (straight_through(mesh, v, edges))
      runs.unite(static_cast<std::uint32_t>(edges[0].idx()), static_cast<std::uint32_t>(edges[1].idx()));
  }
  std::vector<double> run_length(mesh.n_edges(), 0);
  for (const auto e : mesh.edges())
    if (candidate[static_cast<std::size_t>(e.idx())]) run_length[runs.find(static_cast<std::uint32_t>(e.idx()))] += mesh.calc_edge_length(e);
  const double shortest = kShortestCrease * median_edge_length(mesh);
  std::vector<char> crease(mesh.n_edges(), 0);
  for (const auto e : mesh.edges()) {
    const std::size_t i = static_cast<std::size_t>(e.idx());
    if (!candidate[i]) continue;
    crease[i] = run_length[runs.find(static_cast<std::uint32_t>(e.idx()))] >= shortest ||
                (between_planes && has_coplanar_neighbour(mesh, mesh.face_handle(mesh.halfedge_handle(e, 0))) &&
                 has_coplanar_neighbour(mesh, mesh.face_handle(mesh.halfedge_handle(e, 1))));
  }
  return crease;
}

}  // namespace meshprep::detail
