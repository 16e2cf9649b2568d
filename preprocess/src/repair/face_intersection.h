#pragma once
// Repair step 6 (repair.h): where two faces meet, exactly, as the segments each must be cut along.

#include "repair/exact_geometry.h"

#include <vector>

namespace meshprep::detail {

/// A segment of a face's plane to cut the face along; from == to for a single point.
struct CutSegment {
  ExactPoint from, to;
};

/// The cuts the closed triangles a and b make in each other.
struct FaceIntersection {
  std::vector<CutSegment> in_a, in_b;
  bool coplanar = false;  ///< the faces share their plane (each was cut along the other's edges)
};

/// Faces in different planes meet along one segment (or at one point) of the line their planes
/// share: the overlap of the two faces' chords on it, which both are cut along. Coplanar faces
/// overlap in a polygon: each is cut along the other's edges, clipped to it, so that the overlap
/// becomes faces of its own in both. Empty if the faces do not meet.
/// \pre both triangles have area
FaceIntersection intersect_faces(const ExactTriangle& a, const ExactTriangle& b);

}  // namespace meshprep::detail
