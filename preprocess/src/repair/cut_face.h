#pragma once
// Repair step 6 (repair.h): one face triangulated again along the cuts other faces make in it.

#include "repair/exact_geometry.h"
#include "repair/face_intersection.h"

#include <vector>

namespace meshprep::detail {

struct CutFace {
  std::vector<ExactPoint> points;                 ///< the face's corners first, then the cuts' points
  std::vector<std::array<int, 3>> triangles;      ///< into points, oriented as the face
};

/// Triangulates `face` so that every cut (split where cuts cross each other) and every point of
/// `boundary_points` (points of its edges where a neighbour is cut) is made of edges of the
/// result. The triangulation is a greedy one, shortest edges first, over the face's plane projected
/// exactly (exact_geometry.h): every edge added crosses no edge already there and passes through
/// no point, so the edges end as a maximal plane graph whose bounded faces are the triangles.
/// Its cost grows as the cube of the points on the face, a handful where a surface crosses itself.
/// \pre every cut and point lies on the closed face; the face has area
CutFace cut_face(const ExactTriangle& face, const std::vector<CutSegment>& cuts,
                 const std::vector<ExactPoint>& boundary_points);

}  // namespace meshprep::detail
