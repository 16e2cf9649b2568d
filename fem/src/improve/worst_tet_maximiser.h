#pragma once
// Where to put the one free corner shared by a set of tets so that the worst of them is best: a
// non-smooth optimisation solved with Freitag, Jones & Plassmann's active-set method ("An
// efficient parallel algorithm for mesh smoothing", IMR 1995; as in Klingner & Shewchuk, IMR
// 2007). The search direction is the point of smallest norm in the convex hull of the gradients
// of the nearly worst tets (the steepest ascent of their minimum); the step goes to where a
// linearised other tet would become the worst, halved until the worst really gains. Used by the
// smoothing (a vertex's own tets) and the insertion (a cavity's faces joined to the new vertex).

#include "meshprep/core/mesh.h"

#include <functional>
#include <vector>

namespace meshprep::improve {

/// A tet with one free corner: its three fixed corners, in the order that makes the tet
/// (fixed[0], fixed[1], fixed[2], free corner) positively oriented when it is valid.
struct OneFreeCornerTet {
  Vec3 fixed[3];
};

/// The objective's worst over `tets` with the free corner at x.
double worst_quality(const std::vector<OneFreeCornerTet>& tets, const Vec3& x, double obtuse_weight);

struct MaximisedPosition {
  Vec3 position;
  double worst;  ///< the objective's worst over the tets there
};

/// Where the free corner may go when it is not free in space (a boundary vertex sliding on its
/// surface): `direction` keeps the part of a gradient along which it may move (the tangent plane,
/// the crease's line), `position` puts a point back where it may be (onto the surface).
struct SlideConstraint {
  std::function<Vec3(const Vec3&)> direction;
  std::function<Vec3(const Vec3&)> position;
};

/// Starts at `start` and climbs; `max_step` bounds each step's length (a fraction of the local
/// edge lengths keeps the linearisation honest). The result is never worse than the start. With
/// `constraint`, the gradients are those of the constrained corner and every step ends on it.
MaximisedPosition maximise_worst_tet(const std::vector<OneFreeCornerTet>& tets, const Vec3& start, double max_step,
                                     double obtuse_weight, const SlideConstraint* constraint = nullptr);

/// True if every tet is positive at x by the exact orientation test.
bool all_positive(const std::vector<OneFreeCornerTet>& tets, const Vec3& x);

}  // namespace meshprep::improve
