#pragma once
// The statistic that drives the enhancement (enhance.h, step 1).

#include "meshprep/core/mesh.h"
#include "meshprep/preprocess/enhance/enhance.h"

#include <vector>

namespace meshprep::detail {

/// The distribution of q = 1 / radius_ratio over the faces of `mesh` (degenerate faces q = 0).
QualityTail measure_tail(const TriMesh& mesh, double target_min_angle_deg);

/// Per face (by face index): 1 + gamma (tau - q) / s below tau = mean - k s, and at least
/// 1 + gamma for a face whose smallest angle is under the target; 1 elsewhere.
std::vector<double> tail_weights(const TriMesh& mesh, const EnhanceParams& params);

/// Whether `now` is a better distribution than `best`: fewer faces under the target angle, or as
/// many and a 5th percentile of q that closed more than 1 % of its gap to 1 (the equilateral); and,
/// once best's smallest angle has reached half the target, a smallest angle no smaller than
/// min(best's, the target). TetGen keeps a surface's angles in its tets: the femur's later rounds
/// had fewer faces under 20 degrees but a 13.2-degree angle where its kept round has 15.1. Before
/// half the target the count matters more (fandisk without a reference: 12 % -> 5 % under 20
/// degrees while its smallest angle went 0.27 -> 0.01, and on to 4 % and 1.6 degrees).
bool improves(const QualityTail& now, const QualityTail& best, double target_min_angle_deg);

}  // namespace meshprep::detail
