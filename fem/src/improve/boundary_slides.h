#pragma once
// Boundary vertices that slide on the surface. Klingner & Shewchuk ("Aggressive tetrahedral mesh
// improvement", IMR 2007) smooth a boundary vertex within its planar facet or along its straight
// segment, which keeps the domain exactly. Our boundaries are curved as often as flat (a scan, a
// remeshed part), so the reference is the boundary as it was when the improvement began: a
// vertex slides on its own faces of then, along its crease where it lies on one (an edge where the
// surface turns by more than kCreaseTurnDeg, or between two patches), and not at all at a corner
// (any other number of crease edges), on a face between two regions or on a listed inner face.
// A slide is kept only if, besides raising the worst of the vertex's tets as any smoothing step,
// - each boundary face at the vertex turns by at most kMaxFaceTurnDeg from its first normal (the
//   surface does not fold) and keeps its smallest angle at least the smaller of 10 degrees and its
//   first one (the surface's faces under 10 degrees are never more, its smallest angle never less),
// - the faces at the vertex lie within max_deviation of the reference (sampled at their centroids
//   and the midpoints of the edges at the vertex), and the first positions of the vertex and of
//   its neighbours within max_deviation of the faces now around them.
// On a flat facet both hold exactly: the boundary keeps its shape, only its triangles change. The
// faces keep their corners (and so their tags): no move of the improvement changes a boundary
// face's corners.

#include "tet_complex.h"

#include "meshprep/fem/tet_mesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace meshprep::improve {

class BoundarySlides {
 public:
  /// The reference is `mesh`'s boundary now (its faces with one tet); `tagged` gives their tags
  /// (its boundary_faces and boundary_tags; `mesh` was made from it). `max_deviation` in the units
  /// of the mesh, > 0.
  BoundarySlides(const TetComplex& mesh, const TetMesh& tagged, double max_deviation);

  bool may_slide(VertexId v) const { return v < kind_.size() && kind_[v] != Kind::fixed; }

  /// Moves boundary vertex v on its surface where the worst of its tets is better and the
  /// conditions above hold; true if it moved. \pre may_slide(v).
  bool slide(TetComplex& mesh, VertexId v) const;

  /// How far v is from where it began.
  double displacement(const TetComplex& mesh, VertexId v) const { return (mesh.point(v) - first_points_[v]).norm(); }

 private:
  enum class Kind : std::uint8_t { fixed, surface, crease };

  // Whether v at p keeps the surface (the two conditions above).
  bool keeps_surface(const TetComplex& mesh, VertexId v, const Vec3& p) const;
  // The distance from x to the reference faces around v.
  double distance_to_first_fan(VertexId v, const Vec3& x) const;
  // The distance from x to the faces around v now, with `moved` at p.
  double distance_to_fan(const TetComplex& mesh, VertexId v, VertexId moved, const Vec3& p, const Vec3& x) const;
  // The corners of boundary face f now, with `moved` at p.
  std::array<Vec3, 3> corners(const TetComplex& mesh, std::size_t f, VertexId moved, const Vec3& p) const;

  double max_deviation_;
  std::vector<Vec3> first_points_;
  std::vector<std::array<VertexId, 3>> faces_;  ///< the boundary faces, oriented out of the solid
  std::vector<Vec3> first_normals_;             ///< unit, at the start
  std::vector<double> least_angles_deg_;        ///< the smallest angle each face may have
  std::vector<std::uint32_t> fan_start_, fan_;  ///< the faces around each vertex (CSR)
  std::vector<Kind> kind_;
  std::vector<std::array<VertexId, 2>> crease_ends_;  ///< a crease vertex's neighbours along its crease
};

}  // namespace meshprep::improve
