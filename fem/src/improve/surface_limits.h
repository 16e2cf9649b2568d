#pragma once
// What the boundary forbids. At a boundary edge e the tets around it split the solid's interior
// angle alpha there (the sum of their dihedral angles at e). With one tet at e, that tet is forced:
// e joined to the far corners a1, a2 of the two boundary faces at e, whose shape is fixed by the
// surface. With two, they are the two boundary faces joined to one inner point X. With k >= 3, one
// of them has a dihedral angle <= alpha / k <= alpha / 3 at e. So no tets, whatever their inner
// vertices, have a smallest dihedral angle above
//     bound(e) = max(smallest dihedral of the tet (e, a1, a2) if it is a valid tet,
//                    best smallest dihedral of the two tets (face 1, X), (face 2, X) over X,
//                    alpha / 3),
// and a boundary kept exactly caps the whole mesh at the smallest bound. A sharp edge (alpha below
// the goal) is the plain case; a wedge under three times the goal whose one- and two-tet fillings
// are poor is the other (dino's claw: a 31.6-degree wedge whose forced tet has 4.2 degrees and
// whose best split 6.9: at most 10.5). The two-tet term is the best the smoothing's maximiser finds
// from two starts, not a proven maximum: where it decides the bound, a better X could raise it.

#include "tet_complex.h"

#include "meshprep/fem/improve_tets.h"

#include <vector>

namespace meshprep::improve {

/// The boundary at one edge (u, v): its faces (u, v, apex 0) and (v, u, apex 1), oriented out of
/// the solid.
struct BoundaryWedge {
  Vec3 u, v;
  Vec3 apex[2];
};

/// The solid's angle at the edge, in degrees: below 180 where the edge is convex.
double interior_angle_deg(const BoundaryWedge& w);

/// bound(e) above for the edge's wedge of the given interior angle; the one- and two-tet terms are
/// worked out only where the angle alone (alpha / 3) does not reach the goal.
double wedge_bound_deg(const BoundaryWedge& w, double interior_angle_deg, double goal_min_dihedral_deg);

/// The best biased smallest sine (tet_objective.h, with `obtuse_weight`) of any tet on the boundary
/// face (corners oriented out of the solid), as the angle whose sine it is: the tet on it is the
/// face joined to one point, placed by the smoothing's maximiser from two starts. A cap (a face
/// with an angle near 180 degrees) forces a dihedral angle near 0 or 180 on it.
double face_bound_deg(const std::array<Vec3, 3>& face, double obtuse_weight);

/// Every boundary edge (an edge of two constrained faces of one region) whose bound is below
/// `goal_min_dihedral_deg`, lowest bound first.
std::vector<LimitingBoundaryEdge> limiting_boundary_edges(const TetComplex& mesh, double goal_min_dihedral_deg);

}  // namespace meshprep::improve
