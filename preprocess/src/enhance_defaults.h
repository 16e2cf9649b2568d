#pragma once
// The enhancement statistic's constants (enhance.h), fitted by bench/tune_enhance on 2026-11-22
// at commit d140885 (Release, 2-core VM) with `bin/tune_enhance` (its defaults: a 24-point maximin
// Latin hypercube, seed 7, then 3 Ceres quadratic fits, each measured at its minimum; 470 s).
// J is one hinge per goal of issue #7 (max(0, value/goal - 1), or goal/value for the femur's
// smallest angle >= 15 deg; 11 goals over bunny00 10 %, fandisk 30 % and femur) plus
// 0.1 x sum of (radius ratio p95 - 1); lower is better. J 3.657 with these, 3.680 with the
// hand-picked ones they replace (tail_k 1, tail_weight 4, fidelity_weight 1, flip_dihedral_deg 20;
// `tune_enhance --evaluate 1,4,1,20`, same binary). Both meet 7 of the 11 goals: bunny00 5/5,
// fandisk 0/3 (under 20 deg, Hausdorff, RMS: none of the four constants reaches them), femur 2/3
// (smallest angle 14.25 deg with these, 12.98 with the hand-picked, goal 15). The gain is small and
// the surrogate did not predict J (leave-one-out R² -0.08); three of these constants sit at the top
// of the tuner's ranges. Re-run the tuner when enhance changes. Details: bench/RESULTS.md,
// "Enhancement (issue #7)".

namespace meshprep::detail::enhance_defaults {

constexpr double kTailK = 1.83;
constexpr double kTailWeight = 10.0;
constexpr double kFidelityWeight = 100.0;
constexpr double kFlipDihedralDeg = 40.0;

}  // namespace meshprep::detail::enhance_defaults
