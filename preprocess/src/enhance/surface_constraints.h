#pragma once
// What each vertex of a mesh may do while it is relocated on a surface, and where a moved vertex
// is put back: onto the reference surface, or onto its own feature line.

#include "meshprep/core/mesh.h"
#include "meshprep/quality/triangle_bvh.h"

#include <cstdint>
#include <vector>

namespace meshprep::detail {

enum class VertexRole : std::uint8_t {
  Surface,  ///< on no feature: moves in its tangent plane
  Line,     ///< on exactly two feature edges (a crease or the boundary): slides along them
  Fixed     ///< a corner (one, or three or more feature edges, or two turning by over 60 degrees), or non-manifold
};

/// The features of a mesh, found once at the start, kept as properties of the mesh (so that they
/// follow its elements through flips, collapses and garbage collection; flips and collapses never
/// touch a feature edge or a vertex on one, but for a cap's long edge: flip_feature_through_apex).
///
/// Features are boundary edges, the borders between boundary patches (mesh_patches.h) and
/// creases. A crease is a run, at least five median edge lengths
/// long, of edges whose dihedral angles exceed the feature angle, joined at vertices where the run
/// goes nearly straight on (turns by less than 30 degrees) and that have no other such edge. A CAD
/// part's creases are such runs, even where decimation left a long straight edge of the part only
/// two or three edges (fandisk at 30 %); the isolated folds of a rough scan (femur: a quarter of its
/// edges over 45 degrees, in every direction) are not, and stay free to move.
class SurfaceConstraints {
 public:
  /// `mesh` and `reference` must outlive this object, which adds its properties to `mesh` and
  /// removes them when destroyed. With `planar_creases`, a sharp edge between two faces that each
  /// have a neighbour in their own plane is a crease however short its run, and a crease vertex
  /// turning by more than 33 degrees is a corner: a CAD tessellation's (one the enhancement
  /// remeshes).
  SurfaceConstraints(TriMesh& mesh, const TriangleSoup& reference, double feature_angle_deg, bool planar_creases = false);
  ~SurfaceConstraints();
  SurfaceConstraints(const SurfaceConstraints&) = delete;
  SurfaceConstraints& operator=(const SurfaceConstraints&) = delete;

  VertexRole role(TriMesh::VertexHandle v) const { return mesh_.property(role_, v); }
  bool is_feature(TriMesh::EdgeHandle e) const { return mesh_.property(feature_, e) != 0; }

  /// Whether collapsing h would merge a feature edge away: each face that vanishes merges its edge
  /// (v, p) into (w, p), and OpenMesh may keep either handle, so a feature edge (w, p) would lose
  /// its mark, and the line through w its segment.
  bool collapse_merges_feature(TriMesh::HalfedgeHandle h) const;

  /// The two feature edges' other ends of a Line vertex.
  std::pair<TriMesh::VertexHandle, TriMesh::VertexHandle> line_neighbours(TriMesh::VertexHandle v) const;

  /// Where a vertex that moved to x belongs: Surface vertices the closest point of the reference,
  /// raised along the reference's normal by the vertex's offset at the start (a simplified
  /// mesh's vertices sit off the original surface so that its faces follow it: sliding keeps that),
  /// Line vertices the closest point of the feature line they were on at the start (the input's
  /// segments of their run; along a patch border, the reference's border between the same two
  /// patches). Fixed vertices do not move; x is returned.
  Vec3 project(TriMesh::VertexHandle v, const Vec3& x) const;

  /// Splits non-feature edge e at its midpoint, a new Surface vertex at its present distance from
  /// the reference (so that relocation keeps it there), or, with `ends_offset`, at the mean of
  /// its ends' offsets (project() then puts it where its ends' surface is). Returns the new vertex.
  TriMesh::VertexHandle split_surface_edge(TriMesh::EdgeHandle e, bool ends_offset = false);
  /// Splits feature edge e at its midpoint, put on the feature line it runs along: a new Line
  /// vertex on the line of either end (an edge between two corners starts a line of its own
  /// segment). Its two halves stay feature edges. Returns the new vertex.
  TriMesh::VertexHandle split_feature_edge(TriMesh::EdgeHandle e);
  /// Flips feature edge e = (a, b), the long edge of a cap (a, b, apex) (h its halfedge in the
  /// cap), apex a Surface vertex: the feature then runs a-apex-b, apex a Line vertex on the line
  /// of either end (as split_feature_edge puts its new vertex), and the new edge is no feature.
  void flip_feature_through_apex(TriMesh::HalfedgeHandle h);
  /// Closest point of the reference surface to x.
  TriangleBvh::Hit closest_on_reference(const Vec3& x) const { return bvh_.closest_point(x); }
  const TriangleBvh& reference_bvh() const { return bvh_; }
  /// Unit normal of a reference face (zero if it is degenerate).
  Vec3 reference_normal(std::size_t face) const;

 private:
  struct Segment {
    Vec3 a, b;
  };
  /// The line a new vertex on feature edge (a, b) belongs to: either end's, or a new line of the
  /// edge's own segment when both are corners.
  int line_of_feature_edge(TriMesh::VertexHandle a, TriMesh::VertexHandle b);
  void follow_reference_borders(const TriangleSoup& reference);
  TriMesh& mesh_;
  OpenMesh::VPropHandleT<VertexRole> role_;
  OpenMesh::VPropHandleT<int> line_;          ///< Line vertices: index into lines_; -1 otherwise
  OpenMesh::VPropHandleT<double> offset_;     ///< Surface vertices: signed distance to the reference at the start
  OpenMesh::EPropHandleT<char> feature_;
  std::vector<std::vector<Segment>> lines_;   ///< the input's feature segments, one list per line
  TriangleBvh bvh_;
};

}  // namespace meshprep::detail
