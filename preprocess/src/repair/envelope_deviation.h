#pragma once
// Repair's second route (repair.h): how far the rebuilt surface lies from the soup it stands for.

#include "meshprep/core/mesh.h"

#include <cstddef>
#include <vector>

namespace meshprep::detail {

struct DeviationPlace {
  Vec3 point = Vec3::Zero();
  double distance = 0;  ///< in the soup's units
};

struct EnvelopeDeviation {
  double max = 0, rms = 0;        ///< in the soup's units, over both directions' samples
  std::size_t samples = 0;
  std::size_t over_bound = 0;     ///< samples farther than the bound
  std::vector<DeviationPlace> places;  ///< the farthest of them, each its own place
};

/// The distance between `surface` (envelope_surface's) and the outer surface of `soup`, both ways:
/// from `surface` at its vertices, its faces' centres and its edges' middles to the nearest face of
/// the soup; and from the soup's vertices on its outer surface (where the winding number is under
/// one half a thousandth of `cell` outside them, along their normal, and at least one half as far
/// inside) to the nearest face of `surface`. The soup's inner walls (an overlap's, a fold's) are
/// no part of the solid and are not measured. Samples farther than `bound` are counted, and listed
/// as places, the farthest first, no two within 10 `cell`s (a place is the farthest sample of its
/// neighbourhood), at most `max_places`. RMS over every sample alike.
EnvelopeDeviation envelope_deviation(const TriangleSoup& surface, const TriangleSoup& soup, double bound, double cell,
                                     std::size_t max_places);

}  // namespace meshprep::detail
