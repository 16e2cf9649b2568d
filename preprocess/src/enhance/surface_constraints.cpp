#include "enhance/surface_constraints.h"

#include "shared/edge_lengths.h"
#include "shared/triangle_angles.h"

#include "meshprep/core/union_find.h"

#include <algorithm>
#include <cmath>

namespace meshprep::detail {
namespace {

using VertexHandle = TriMesh::VertexHandle;
using EdgeHandle = TriMesh::EdgeHandle;

const double kStraightCosine = std::cos(150.0 * M_PI / 180.0);  // a run turns by less than 30 degrees
// A vertex whose two feature edges turn by more than 60 degrees (midway between going straight
// on and a right angle) is a corner of the part: it stays. Sliding it along either edge would cut
// the other one's end off (fandisk: 3e-3 of the diagonal at a box corner). The femur's noise
// creases bend by less, and keep their vertices free to slide (TetGen 5.5 degrees, 4.4 when
// every turning vertex was fixed).
const double kCornerCosine = std::cos(120.0 * M_PI / 180.0);
// Remeshing a tessellation that lies on its reference (a CAD export), a crease turning by more
// than 33 degrees is a corner as well: the export's crease lines are the part's edges, and a
// vertex sliding past such a kink cut it by 1.07e-3 of the diagonal (example007, 47 degrees),
// above the 1e-3 goal. 33 is no regular polygon's turn (360 / n), where round-off would decide.
const double kRemeshCornerCosine = std::cos((180.0 - 33.0) * M_PI / 180.0);
constexpr double kShortestCrease = 5;                             // median edge lengths

Vec3 point(const TriMesh& mesh, VertexHandle v) { return to_eigen(mesh.point(v)); }

bool sharp(const TriMesh& mesh, EdgeHandle e, double cos_feature) {
  const Vec3 n0 = to_eigen(mesh.calc_face_normal(mesh.face_handle(mesh.halfedge_handle(e, 0))));
  const Vec3 n1 = to_eigen(mesh.calc_face_normal(mesh.face_handle(mesh.halfedge_handle(e, 1))));
  const double norms = n0.norm() * n1.norm();
  return norms > 0 && n0.dot(n1) < cos_feature * norms;
}

VertexHandle other_end(const TriMesh& mesh, EdgeHandle e, VertexHandle v) {
  const VertexHandle a = mesh.to_vertex_handle(mesh.halfedge_handle(e, 0));
  return a == v ? mesh.to_vertex_handle(mesh.halfedge_handle(e, 1)) : a;
}

// The feature edges of each vertex.
std::vector<std::vector<EdgeHandle>> incident(const TriMesh& mesh, const std::vector<char>& feature) {
  std::vector<std::vector<EdgeHandle>> edges(mesh.n_vertices());
  for (const auto e : mesh.edges())
    if (feature[static_cast<std::size_t>(e.idx())])
      for (int i : {0, 1}) edges[static_cast<std::size_t>(mesh.to_vertex_handle(mesh.halfedge_handle(e, i)).idx())].push_back(e);
  return edges;
}

// A vertex where a run of sharp edges goes straight on: exactly two of them, nearly opposite.
// (`cosine`: of the smallest angle between the two edges that still counts as straight on.)
bool straight_through(const TriMesh& mesh, VertexHandle v, const std::vector<EdgeHandle>& edges,
                      double cosine = kStraightCosine) {
  if (edges.size() != 2) return false;
  const Vec3 x = point(mesh, v);
  const Vec3 a = point(mesh, other_end(mesh, edges[0], v)) - x, b = point(mesh, other_end(mesh, edges[1], v)) - x;
  return a.dot(b) <= cosine * a.norm() * b.norm();
}

// Whether face f has a neighbour in its plane (within kCoplanarCosine) across one of its edges.
bool has_coplanar_neighbour(const TriMesh& mesh, TriMesh::FaceHandle f) {
  const Vec3 n = to_eigen(mesh.calc_face_normal(f));
  for (const auto h : mesh.fh_range(f)) {
    const auto g = mesh.opposite_face_handle(h);
    if (g.is_valid() && n.dot(to_eigen(mesh.calc_face_normal(g))) > kCoplanarCosine) return true;
  }
  return false;
}

// Sharp interior edges that belong to a run at least kShortestCrease median edge lengths long:
// isolated sharp edges of a scan's noise are no feature, a CAD part's long straight edge is even
// when simplification left it only two or three edges (fandisk after CGAL's decimation). With
// `between_planes`, also those whose two faces each have a neighbour in their plane: a CAD
// tessellation's edge between two planes (a box of twelve triangles has runs of one edge; a
// scan's faces almost never have such neighbours: 0.5 % of the femur's edges are flat).
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

}  // namespace

SurfaceConstraints::SurfaceConstraints(TriMesh& mesh, const TriangleSoup& reference, double feature_angle_deg,
                                       bool planar_creases)
    : mesh_(mesh), bvh_(reference) {
  mesh_.add_property(role_);
  mesh_.add_property(line_);
  mesh_.add_property(offset_);
  mesh_.add_property(feature_);
  std::vector<char> feature = creases(mesh, std::cos(feature_angle_deg * M_PI / 180.0), planar_creases);
  for (const auto e : mesh.edges())
    if (mesh.is_boundary(e)) feature[static_cast<std::size_t>(e.idx())] = 1;
  for (const auto e : mesh.edges()) mesh_.property(feature_, e) = feature[static_cast<std::size_t>(e.idx())];
  const auto edges_of = incident(mesh, feature);
  for (const auto v : mesh.vertices()) {
    const std::size_t degree = edges_of[static_cast<std::size_t>(v.idx())].size();
    VertexRole role = VertexRole::Surface;
    // A corner (three or more feature edges, or two that turn sharply) stays; so does a line's end.
    if (!mesh.is_manifold(v) || (degree != 0 && degree != 2)) role = VertexRole::Fixed;
    else if (degree == 2)
      role = straight_through(mesh, v, edges_of[static_cast<std::size_t>(v.idx())], planar_creases ? kRemeshCornerCosine : kCornerCosine) ? VertexRole::Line
                                                                                                    : VertexRole::Fixed;
    mesh_.property(role_, v) = role;
    mesh_.property(line_, v) = -1;
    const TriangleBvh::Hit hit = bvh_.closest_point(point(mesh, v));
    mesh_.property(offset_, v) = (point(mesh, v) - hit.point).dot(reference_normal(hit.face));
  }
  // A line: Line vertices joined by feature edges; its segments are every feature edge that
  // touches one of them (the segments ending at a corner belong to it as well).
  UnionFind lines(mesh.n_vertices());
  for (const auto e : mesh.edges()) {
    if (!is_feature(e)) continue;
    const VertexHandle a = mesh.to_vertex_handle(mesh.halfedge_handle(e, 0)), b = mesh.to_vertex_handle(mesh.halfedge_handle(e, 1));
    if (role(a) == VertexRole::Line && role(b) == VertexRole::Line)
      lines.unite(static_cast<std::uint32_t>(a.idx()), static_cast<std::uint32_t>(b.idx()));
  }
  std::vector<int> line_of_root(mesh.n_vertices(), -1);
  for (const auto v : mesh.vertices()) {
    if (role(v) != VertexRole::Line) continue;
    int& index = line_of_root[lines.find(static_cast<std::uint32_t>(v.idx()))];
    if (index < 0) {
      index = static_cast<int>(lines_.size());
      lines_.emplace_back();
    }
    mesh_.property(line_, v) = index;
  }
  for (const auto e : mesh.edges()) {
    if (!is_feature(e)) continue;
    const VertexHandle a = mesh.to_vertex_handle(mesh.halfedge_handle(e, 0)), b = mesh.to_vertex_handle(mesh.halfedge_handle(e, 1));
    const int line = role(a) == VertexRole::Line ? mesh_.property(line_, a) : mesh_.property(line_, b);
    if (line >= 0) lines_[static_cast<std::size_t>(line)].push_back({point(mesh, a), point(mesh, b)});
  }
}

SurfaceConstraints::~SurfaceConstraints() {
  mesh_.remove_property(role_);
  mesh_.remove_property(line_);
  mesh_.remove_property(offset_);
  mesh_.remove_property(feature_);
}

Vec3 SurfaceConstraints::reference_normal(std::size_t face) const { return unit_normal(bvh_.surface(), face); }

bool SurfaceConstraints::collapse_merges_feature(TriMesh::HalfedgeHandle h) const {
  for (const auto side : {h, mesh_.opposite_halfedge_handle(h)}) {
    if (mesh_.is_boundary(side)) continue;
    const auto next = mesh_.next_halfedge_handle(side);
    if (is_feature(mesh_.edge_handle(next)) || is_feature(mesh_.edge_handle(mesh_.next_halfedge_handle(next)))) return true;
  }
  return false;
}

std::pair<VertexHandle, VertexHandle> SurfaceConstraints::line_neighbours(VertexHandle v) const {
  VertexHandle ends[2];
  int found = 0;
  for (const auto h : mesh_.voh_range(v))
    if (is_feature(mesh_.edge_handle(h)) && found < 2) ends[found++] = mesh_.to_vertex_handle(h);
  return {ends[0], ends[1]};
}

TriMesh::VertexHandle SurfaceConstraints::split_surface_edge(EdgeHandle e, bool ends_offset) {
  const auto h = mesh_.halfedge_handle(e, 0);
  const VertexHandle a = mesh_.from_vertex_handle(h), b = mesh_.to_vertex_handle(h);
  const Vec3 middle = 0.5 * (point(mesh_, a) + point(mesh_, b));
  const VertexHandle m = mesh_.add_vertex(to_openmesh(middle));
  mesh_.split(e, m);
  mesh_.property(role_, m) = VertexRole::Surface;
  mesh_.property(line_, m) = -1;
  if (ends_offset) {
    mesh_.property(offset_, m) = 0.5 * (mesh_.property(offset_, a) + mesh_.property(offset_, b));
  } else {
    const TriangleBvh::Hit hit = bvh_.closest_point(middle);
    mesh_.property(offset_, m) = (middle - hit.point).dot(reference_normal(hit.face));
  }
  for (const auto out : mesh_.voh_range(m)) mesh_.property(feature_, mesh_.edge_handle(out)) = 0;
  return m;
}

int SurfaceConstraints::line_of_feature_edge(VertexHandle a, VertexHandle b) {
  int line = role(a) == VertexRole::Line ? mesh_.property(line_, a) : -1;
  if (line < 0 && role(b) == VertexRole::Line) line = mesh_.property(line_, b);
  if (line < 0) {
    line = static_cast<int>(lines_.size());
    lines_.push_back({{point(mesh_, a), point(mesh_, b)}});
  }
  return line;
}

void SurfaceConstraints::flip_feature_through_apex(TriMesh::HalfedgeHandle h) {
  const VertexHandle a = mesh_.from_vertex_handle(h), b = mesh_.to_vertex_handle(h);
  const VertexHandle apex = mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h));
  const int line = line_of_feature_edge(a, b);
  const EdgeHandle e = mesh_.edge_handle(h);
  mesh_.flip(e);
  mesh_.property(feature_, e) = 0;
  mesh_.property(feature_, mesh_.edge_handle(mesh_.find_halfedge(apex, a))) = 1;
  mesh_.property(feature_, mesh_.edge_handle(mesh_.find_halfedge(apex, b))) = 1;
  mesh_.property(role_, apex) = VertexRole::Line;
  mesh_.property(line_, apex) = line;
  mesh_.property(offset_, apex) = 0;
}

TriMesh::VertexHandle SurfaceConstraints::split_feature_edge(EdgeHandle e) {
  const auto h = mesh_.halfedge_handle(e, 0);
  const VertexHandle a = mesh_.from_vertex_handle(h), b = mesh_.to_vertex_handle(h);
  const int line = line_of_feature_edge(a, b);
  const TriMesh::Point at_a = mesh_.point(a);  // a copy: adding a vertex may move the points
  const VertexHandle m = mesh_.add_vertex(at_a);
  mesh_.property(role_, m) = VertexRole::Line;
  mesh_.property(line_, m) = line;
  mesh_.property(offset_, m) = 0;
  mesh_.set_point(m, to_openmesh(project(m, 0.5 * (point(mesh_, a) + point(mesh_, b)))));
  mesh_.split(e, m);
  for (const auto out : mesh_.voh_range(m)) {
    const VertexHandle end = mesh_.to_vertex_handle(out);
    mesh_.property(feature_, mesh_.edge_handle(out)) = end == a || end == b;
  }
  return m;
}

Vec3 SurfaceConstraints::project(VertexHandle v, const Vec3& x) const {
  switch (role(v)) {
    case VertexRole::Surface: {
      const TriangleBvh::Hit hit = bvh_.closest_point(x);
      return hit.point + mesh_.property(offset_, v) * reference_normal(hit.face);
    }
    case VertexRole::Line: {
      Vec3 best = x;
      double best_distance = INFINITY;
      for (const Segment& s : lines_[static_cast<std::size_t>(mesh_.property(line_, v))]) {
        const Vec3 p = closest_point_on_segment(x, s.a, s.b);
        const double d = (p - x).squaredNorm();
        if (d < best_distance) best_distance = d, best = p;
      }
      return best;
    }
    case VertexRole::Fixed:
      break;
  }
  return x;
}

}  // namespace meshprep::detail
