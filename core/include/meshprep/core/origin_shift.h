#pragma once
/// \file origin_shift.h
/// Work next to the origin. Far from it (survey coordinates, a part placed at 1e9) a double keeps
/// few bits for the shape, and the products of coordinates that quadrics, plane offsets and volumes
/// form lose the rest: a unit sphere at 1e9 simplified into another surface than the same sphere at
/// 0 (tests/cli_corpus_test.sh). The stages therefore run on the surface moved next to the origin.

#include "meshprep/core/mesh.h"
#include "meshprep/core/soup_view.h"

#include <vector>

namespace meshprep {

/// The shift that brings points lying far from the origin next to it: per axis, the centre of
/// their bounding box where that centre is farther from 0 than the box is wide, else 0 (points near
/// the origin are left alone). Subtracting it is exact (every coordinate is within a factor 2 of the
/// centre, Sterbenz's lemma), and adding it back restores each coordinate bit for bit.
Vec3 origin_shift(const PointSpan& points);

/// Moves a mesh by minus its origin_shift for as long as it lives, and back when destroyed (also
/// when an exception leaves the scope). Vertices that did not move in between come back exactly.
class ShiftedToOrigin {
 public:
  explicit ShiftedToOrigin(TriMesh& mesh);
  ~ShiftedToOrigin();
  ShiftedToOrigin(const ShiftedToOrigin&) = delete;
  ShiftedToOrigin& operator=(const ShiftedToOrigin&) = delete;

  /// A copy of `soup` moved the same way (a reference surface that goes with the mesh).
  TriangleSoup moved(const TriangleSoup& soup) const;
  /// What was subtracted from every point.
  const Vec3& shift() const { return shift_; }

 private:
  TriMesh& mesh_;
  Vec3 shift_;
};

}  // namespace meshprep
