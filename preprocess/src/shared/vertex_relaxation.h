#pragma once
// What the two relaxations after the collapses share (shape_polish.h on the quadrics,
// reference_relaxation.h on the original surface): which vertices may move, where a vertex goes,
// and which vertices are on a feature and must stay.

#include "meshprep/core/mesh.h"
#include "meshprep/core/mesh_patches.h"

#include <optional>
#include <vector>

namespace meshprep::detail {

/// The faces that miss a shape goal of issue #4 (radius ratio p95 at most 2.0; few faces under
/// the minimum angle): a radius ratio over `ratio` or a smallest angle whose cosine is over
/// `min_angle_cosine`. After the collapses only the vertices of such faces are relaxed; the other
/// vertices stay where the collapses and their error estimates put them (bunny00 at 10 %: RMS
/// distance 1.57e-4 when every vertex is relaxed, 1.54e-4).
struct ShapeTail {
  double ratio = 2.0;
  double min_angle_cosine = 1.0;
};

/// An interior manifold vertex of valence 3 or more that is not deleted nor on a patch border (a
/// border stays where it is): what the relaxations and the fit to the original (surface_fit.h) may
/// move.
bool relaxable(const TriMesh& mesh, TriMesh::VertexHandle v, const FacePatches& patches);

/// Whether a face around v is in the tail.
bool in_tail(const TriMesh& mesh, TriMesh::VertexHandle v, const ShapeTail& tail);

/// The largest radius ratio of the faces around v with v at `at` (infinity if one has no area).
double worst_radius_ratio(const TriMesh& mesh, TriMesh::VertexHandle v, const Vec3& at);

/// Vertex v moved to the centroid of its 1-ring in its tangent plane (normal: the sum of its
/// faces' area normals).
struct TangentialMove {
  Vec3 from = Vec3::Zero();
  Vec3 to = Vec3::Zero();
  Vec3 normal = Vec3::Zero();  ///< unit
  double reach = 0;            ///< the longest edge at v
};

/// Nothing when v's faces have no area.
std::optional<TangentialMove> tangential_move(const TriMesh& mesh, TriMesh::VertexHandle v);

/// Whether v is on a sharp edge or a corner, where a tangential move would round the feature
/// off: the paper's surface variation sigma = lambda1 / (lambda1 + lambda2 + lambda3) of v and its
/// 1-ring over that of a 30-degree crease. `ring` is scratch space.
bool on_feature(const TriMesh& mesh, TriMesh::VertexHandle v, std::vector<Vec3>& ring);

}  // namespace meshprep::detail
