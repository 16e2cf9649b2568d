#pragma once
// Repair step 5's default (repair.h): which boundary loop is an open sheet's outline, to be left
// open, and which is a hole in a surface, to be filled.

#include "meshprep/core/mesh.h"

#include <cstdint>
#include <vector>

namespace meshprep::detail {

/// One boundary loop as fill_holes walks it.
struct LoopBorder {
  std::uint32_t face = 0;           ///< a face along it
  Vec3 vector_area = Vec3::Zero();  ///< half the sum of p_i x p_i+1 around it, as its faces run it
  bool closes = false;              ///< whether it comes back to its start
};

/// What the rule says of one loop.
struct LoopSheet {
  /// Its component's (P - N) / (P + N): P and N the areas of the shadows that its faces turned
  /// towards and away from d cast on the plane across d, d along the sum of its face normals
  /// weighted by area. 1 for a height field over that plane (no face turns away), 0 for a closed
  /// surface; sheet_outlines.cpp says where other shapes fall.
  double one_sidedness = 0;
  bool outline = false;  ///< the closed loop of its component enclosing the most shadow on that plane
};

/// Above this one-sidedness a component is an open sheet, whose outline is not a hole: less than a
/// tenth of its shadow, (1 - 0.8) / 2, is cast by faces turned away. Every height field is 1 (a
/// terrain, a mask, a strip, an open box, a bowl up to a hemisphere); a spherical cap reaches 0.8
/// at 109.5 degrees (cos = -1/3), 20 past the hemisphere; the scans whose openings are missing parts
/// of a solid measure 0.51 and less (lion; mushroom 0.45, head 0.28), a tube open at both ends 0.
/// Noise folds faces and lowers it: three_peaks (1.0000) with each coordinate moved at random by up
/// to 0.3 and 0.5 x the median edge measures 0.99 and 0.91.
inline constexpr double kSheetOneSidedness = 0.8;

/// The rule's figures for each of `loops` of the oriented, manifold `soup` (components are the
/// faces sharing vertices).
std::vector<LoopSheet> sheet_outlines(const TriangleSoup& soup, const std::vector<LoopBorder>& loops);

}  // namespace meshprep::detail
