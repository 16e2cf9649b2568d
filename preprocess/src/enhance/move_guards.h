#pragma once
// Step 4 of the enhancement (enhance.h): the moves of a round that must be taken back.

#include "enhance/surface_constraints.h"

#include "meshprep/core/mesh.h"
#include "meshprep/core/soup_view.h"
#include "meshprep/quality/triangle_bvh.h"

#include <cstddef>
#include <vector>

namespace meshprep::detail {

/// Distance of every probe (points of the reference: reference_cover.h) to the mesh, and the face
/// where it is reached.
std::vector<TriangleBvh::Hit> reference_coverage(const TriMesh& mesh, const std::vector<Vec3>& probes);

/// Takes back, vertex by vertex (to where the round found it), every move that:
/// - turns a face by more than 60 degrees (or folds it over);
/// - carries a face (its centroid or an edge midpoint) farther from the reference than the bound,
///   and than it was;
/// - leaves a probe of the reference (its vertices, and points along its bent edges where
///   reference_probes() adds them) farther from the mesh than allowed (the bound, or the input's
///   own distance);
/// - makes the surface cross itself beyond the pairs the input had.
/// Putting a vertex back can upset another guard (a face half old, half new), so the guards run
/// in passes until none puts anything back; each pass measures only what the previous one changed.
/// What enforce() found: the vertices the round moved, and those each guard put back.
struct UndoneMoves {
  std::size_t moved = 0;          ///< vertices the round moved
  std::size_t bad_faces = 0;      ///< put back: a face turned, folded or left the bound
  std::size_t uncovering = 0;     ///< put back: a probe of the reference left too far from the mesh
  std::size_t intersections = 0;  ///< put back: the surface crossed itself
  std::size_t total() const { return bad_faces + uncovering + intersections; }
  UndoneMoves& operator+=(const UndoneMoves& other);
};

class MoveGuards {
 public:
  /// `mesh` as the round found it (before any move); its topology must not change until enforce().
  /// `allowed_distance` holds one distance per probe.
  MoveGuards(const TriMesh& mesh, const SurfaceConstraints& constraints, const std::vector<Vec3>& probes,
             const std::vector<double>& allowed_distance, std::size_t allowed_intersections, double max_deviation);

  UndoneMoves enforce(TriMesh& mesh) const;

 private:
  std::size_t undo_bad_faces(TriMesh& mesh, const std::vector<char>& dirty) const;
  std::size_t undo_uncovering(TriMesh& mesh, const std::vector<char>& dirty, std::vector<std::size_t>& nearest_face) const;
  bool moved(const TriMesh& mesh, TriMesh::VertexHandle v) const;
  std::size_t put_back(TriMesh& mesh, TriMesh::FaceHandle f) const;

  const SurfaceConstraints& constraints_;
  const std::vector<Vec3>& probes_;
  const std::vector<double>& allowed_distance_;
  std::size_t allowed_intersections_;
  double max_deviation_;
  std::vector<TriMesh::Point> before_;
  std::vector<TriangleBvh::Hit> coverage_before_;
};

}  // namespace meshprep::detail
