#pragma once
// The objective of tet improvement: the biased minimum sine of a tet's six dihedral angles.
//
// Why the sine: it is zero for a tet with a dihedral angle of 0 or 180 degrees and only then, so
// one number penalises both kinds of bad tet (slivers, needles, caps, wedges) that break a finite
// element's conditioning and interpolation (Shewchuk, "What is a good linear finite element?",
// 2002), it is cheap (no trigonometry), smooth wherever the smallest term is unique, and negative
// for an inverted tet. Why biased: the sine alone rates a 165-degree angle like a 15-degree one,
// and large angles hurt interpolation more than small ones; Klingner & Shewchuk ("Aggressive
// tetrahedral mesh improvement", IMR 2007) weight the obtuse angles' sines by a factor < 1. Here
// the factor makes the two goals of ImproveParams equally bad: weight = sin(goal_min) /
// sin(180 - goal_max), so with 15 and 160 degrees a 160-degree angle scores like a 15-degree one.
//
// sin(theta_kl) = 6V |e_kl| / (|n_k| |n_l|): n_k, n_l the area vectors (twice the area) of the two
// faces meeting at edge e_kl, V the signed volume. The angle is obtuse when the outward normals
// point to the same side (n_k . n_l > 0: the interior angle is pi minus the angle between them).
// A flat or inverted tet scores 6V / (sum of squared edges)^(3/2) <= 0 instead: scale-free, and
// rising as the tet un-inverts.

#include "meshprep/core/mesh.h"

namespace meshprep::improve {

/// The least rise of a worst sine that counts as a gain: 1e-3, about 0.06 degrees near 15. A
/// smoothing step must gain this much (smaller gains only feed the queue with the same tets again;
/// Stellar's MINSMOOTHIMPROVEMENT plays the same role), and so must a pass's worst tet when the
/// count below the goal does not fall (improve_tets.cpp).
inline constexpr double kMinSineGain = 1e-3;

/// Biased minimum sine of the dihedral angles of the tet (p0, p1, p2, p3): in (0, 1] for a
/// positively oriented tet ((p1 - p0) . ((p2 - p0) x (p3 - p0)) > 0), <= 0 for a flat or inverted
/// one. `obtuse_weight` in (0, 1] multiplies the sines of obtuse angles.
double biased_min_sine(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, double obtuse_weight);

/// The same with p3 free, and its gradient with respect to p3 (that of the smallest term; a
/// subgradient where two terms tie).
struct ObjectiveWithGradient {
  double value;
  Vec3 gradient;
};
ObjectiveWithGradient biased_min_sine_gradient(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3,
                                               double obtuse_weight);

}  // namespace meshprep::improve
