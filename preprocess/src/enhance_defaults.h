#pragma once
// The enhancement statistic's constants (enhance.h). Provisional hand-picked values until
// bench/tune_enhance fits them.

namespace meshprep::detail::enhance_defaults {

constexpr double kTailK = 1.0;
constexpr double kTailWeight = 4.0;
constexpr double kFidelityWeight = 1.0;
constexpr double kFlipDihedralDeg = 20.0;

}  // namespace meshprep::detail::enhance_defaults
