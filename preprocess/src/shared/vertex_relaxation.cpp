#include "shared/vertex_relaxation.h"

#include "shared/triangle_angles.h"

#include "meshprep/preprocess/rbf/local_frame.h"
#include "meshprep/quality/triangle_metrics.h"

#include <algorithm>

namespace meshprep::detail {
namespace {

// The paper's 0.3 never fires on a 1-ring (a 90-degree crease gives sigma ~0.13), so the threshold
// is sigma of a 30-degree crease, ~0.015: creases, corners and strongly curved tips are kept.
constexpr double kFeatureVariation = 0.015;

Vec3 point(const TriMesh& mesh, TriMesh::VertexHandle v) { return to_eigen(mesh.point(v)); }

}  // namespace

// One walk around v instead of OpenMesh's is_boundary, is_manifold and valence (the library's are
// out of line and check every handle): a vertex with no outgoing boundary halfedge is interior and
// manifold, OpenMesh keeping a boundary halfedge as the outgoing one wherever there is one.
bool relaxable(const TriMesh& mesh, TriMesh::VertexHandle v, const FacePatches& patches) {
  if (mesh.status(v).deleted() || on_patch_border(patches, mesh, v)) return false;
  int valence = 0;
  for (const auto h : mesh.voh_range(v)) {
    if (mesh.is_boundary(h)) return false;
    ++valence;
  }
  return valence >= 3;
}

bool in_tail(const TriMesh& mesh, TriMesh::VertexHandle v, const ShapeTail& tail) {
  for (const auto f : mesh.vf_range(v)) {
    auto h = mesh.halfedge_handle(f);
    const Vec3 a = point(mesh, mesh.from_vertex_handle(h)), b = point(mesh, mesh.to_vertex_handle(h));
    const Vec3 c = point(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h)));
    if (radius_ratio(a, b, c) > tail.ratio || smallest_angle_cosine(a, b, c) > tail.min_angle_cosine) return true;
  }
  return false;
}

double worst_radius_ratio(const TriMesh& mesh, TriMesh::VertexHandle v, const Vec3& at) {
  double worst = 0;
  for (const auto h : mesh.voh_range(v)) {
    if (mesh.is_boundary(h)) continue;
    worst = std::max(worst, radius_ratio(at, point(mesh, mesh.to_vertex_handle(h)),
                                         point(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h)))));
  }
  return worst;
}

std::optional<TangentialMove> tangential_move(const TriMesh& mesh, TriMesh::VertexHandle v) {
  TangentialMove move;
  move.from = point(mesh, v);
  Vec3 centroid = Vec3::Zero(), normal = Vec3::Zero();
  for (const auto w : mesh.vv_range(v)) {
    centroid += point(mesh, w);
    move.reach = std::max(move.reach, (point(mesh, w) - move.from).norm());
  }
  centroid /= static_cast<double>(mesh.valence(v));
  for (const auto f : mesh.vf_range(v)) {
    auto h = mesh.halfedge_handle(f);
    normal += area_normal(point(mesh, mesh.from_vertex_handle(h)), point(mesh, mesh.to_vertex_handle(h)),
                          point(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h))));
  }
  if (!(normal.norm() > 0)) return std::nullopt;
  move.normal = normal.normalized();
  move.to = centroid - move.normal * move.normal.dot(centroid - move.from);
  return move;
}

bool on_feature(const TriMesh& mesh, TriMesh::VertexHandle v, std::vector<Vec3>& ring) {
  ring.assign(1, point(mesh, v));
  for (const auto w : mesh.vv_range(v)) ring.push_back(point(mesh, w));
  return pca_frame(ring).surface_variation() > kFeatureVariation;
}

}  // namespace meshprep::detail
