#include "enhance/surface_constraints.h"

#include "shared/creases.h"
#include "shared/triangle_angles.h"

#include "meshprep/core/mesh_patches.h"
#include "meshprep/core/union_find.h"
#include "meshprep/quality/face_edges.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace meshprep::detail {
namespace {

using VertexHandle = TriMesh::VertexHandle;
using EdgeHandle = TriMesh::EdgeHandle;

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

Vec3 point(const TriMesh& mesh, VertexHandle v) { return to_eigen(mesh.point(v)); }

}  // namespace

SurfaceConstraints::SurfaceConstraints(TriMesh& mesh, const TriangleSoup& reference, double feature_angle_deg,
                                       bool planar_creases)
    : mesh_(mesh), bvh_(reference) {
  mesh_.add_property(role_);
  mesh_.add_property(line_);
  mesh_.add_property(offset_);
  mesh_.add_property(feature_);
  std::vector<char> feature = creases(mesh, std::cos(feature_angle_deg * M_PI / 180.0), planar_creases);
  const FacePatches patches(mesh);
  for (const auto e : mesh.edges())
    if (mesh.is_boundary(e) || patches.border(e)) feature[static_cast<std::size_t>(e.idx())] = 1;
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
  follow_reference_borders(reference);
}

// A line along a patch border slides on the reference's border between the same two patches,
// not on its own edges: after simplification those are chords of it (a curved border that is no
// crease would move off by their sag, 8e-3 of the diagonal on a sphere's equator).
void SurfaceConstraints::follow_reference_borders(const TriangleSoup& reference) {
  const FacePatches patches(mesh_);
  if (!patches.present() || reference.patches.size() != reference.triangles.size()) return;
  // By value: std::minmax returns references, here to the lambda's own parameters, which are gone
  // when the key is read (at -O3 the map got garbage keys and the lines far-away segments).
  const auto pair_key = [](int p, int q) { return std::pair<int, int>(std::min(p, q), std::max(p, q)); };
  std::map<std::pair<int, int>, std::vector<Segment>> borders;
  const std::vector<FaceEdge> uses = sorted_face_edges(reference);
  for (std::size_t i = 0; i + 1 < uses.size(); ++i) {
    if (uses[i].key != uses[i + 1].key || (i + 2 < uses.size() && uses[i + 2].key == uses[i].key)) continue;
    const int p = reference.patches[uses[i].face], q = reference.patches[uses[i + 1].face];
    if (p != q) borders[pair_key(p, q)].push_back({reference.points[uses[i].lo()], reference.points[uses[i].hi()]});
  }
  std::vector<char> replaced(lines_.size(), 0);
  for (const auto e : mesh_.edges()) {
    if (!patches.border(e)) continue;
    const VertexHandle a = mesh_.to_vertex_handle(mesh_.halfedge_handle(e, 0)), b = mesh_.to_vertex_handle(mesh_.halfedge_handle(e, 1));
    const int line = role(a) == VertexRole::Line ? mesh_.property(line_, a) : mesh_.property(line_, b);
    if (line < 0 || replaced[static_cast<std::size_t>(line)]) continue;
    const auto border = borders.find(pair_key(patches.of(mesh_.face_handle(mesh_.halfedge_handle(e, 0))),
                                              patches.of(mesh_.face_handle(mesh_.halfedge_handle(e, 1)))));
    if (border == borders.end()) continue;
    lines_[static_cast<std::size_t>(line)] = border->second;
    replaced[static_cast<std::size_t>(line)] = 1;
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
  inherit_split_patches(mesh_, m, a, b);
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
  // The crease then runs a-apex-b: both faces lie on the side of the face without the apex.
  const FacePatches patches(mesh_);
  const int far_side = patches.of(mesh_.opposite_face_handle(h));
  mesh_.flip(e);
  if (patches.present())
    for (const int i : {0, 1}) set_face_patch(mesh_, mesh_.face_handle(mesh_.halfedge_handle(e, i)), far_side);
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
  inherit_split_patches(mesh_, m, a, b);
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
