#pragma once
// The simplifier's queue order on big meshes (SimplifyParams::banded_queue_from_edges).
//
// The exact order takes the cheapest edge next, wherever it is: on a big mesh each collapse then
// jumps across the surface and waits on memory for its neighbourhood (at 1.2 M faces a collapse
// cost twice what it costs at 75 k). The banded order takes the edges in bands of costs within a
// factor of one another, each band place by place: by blocks of consecutive edge numbers, which
// follow the Morton order of the vertices (in_spatial_order), the cheapest first within a block.
// A band then sweeps the surface once and a collapse finds most of its neighbourhood in the cache.

#include <cmath>
#include <cstddef>

namespace meshprep::detail {

class BandedOrder {
 public:
  /// For edge numbers in [0, edges); costs within `band_factor` (> 1) of one another share a band;
  /// a block is 2^block_shift edge numbers.
  BandedOrder(std::size_t edges, double band_factor, int block_shift)
      : blocks_(static_cast<double>((edges >> block_shift) + 1)), log_band_(std::log(band_factor)), shift_(block_shift) {}

  /// The heap key of an edge: its band, then its block, then its cost within the band. Costs of
  /// 0 (and below) come first, by block.
  double key(double cost, int edge) const {
    const double exponent = cost > 0 ? std::log(cost) / log_band_ : kFirstBand;
    const double band = std::floor(exponent);
    return band * blocks_ + static_cast<double>(edge >> shift_) + (exponent - band);
  }

 private:
  // Below any cost's band (the smallest positive double is in band -4,083 at a factor of 1.2), with
  // room for band * blocks to stay an exact integer.
  static constexpr double kFirstBand = -1e6;
  double blocks_, log_band_;
  int shift_;
};

}  // namespace meshprep::detail
