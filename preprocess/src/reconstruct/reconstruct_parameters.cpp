#include "meshprep/preprocess/reconstruct/reconstruct_parameters.h"

#include <limits>

namespace meshprep {

const ReconstructParameters& reconstruct_parameters() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  static const ReconstructParameters parameters{
      {"resolution", "--resolution", "grid vertices along the footprint: NX NY", {2, 100000}},
      {"spacing", "--spacing", "grid spacing in the reference plane instead of the resolution; 0 = use the resolution",
       {0, inf, false, true}},
      {"vertices", "--vertices",
       "about this many grid vertices, on square cells, instead of the resolution or the spacing; 0 = use those",
       {0, 100000000}},
      {"leaf_size", "--leaf-size", "K: samples per k-d tree cell (one local patch each)", {1, 100000}},
      {"neighbors", "--neighbors", "samples interpolated by each cell's patch (a Duchon r^2.5 spline)", {3, 1000}},
      {"variation_threshold", "--variation-threshold",
       "patches whose surface variation sigma exceeds this grow (more samples, larger support): a value (the "
       "paper's 0.3) or a percentile of the patches' sigma (p90)",
       {}},
      {"variation_growth", "--variation-growth", "support radius factor of a grown patch (its samples grow by the square)",
       {1, 4}},
      {"max_gap", "--max-gap", "triangles farther than this from every sample are left out (0 = 3x the median sample spacing)",
       {0, inf, false, true}},
      {"fill_holes", "--fill-holes",
       "keep the triangles over gaps inside the footprint (flagged in the JSON) and only the largest piece, so the "
       "surface has one boundary loop and can be closed into a block",
       {}},
      {"adaptive", "--adaptive",
       "vertices dense where the surface bends, sparse where flat, for about the same face count (the twice finer "
       "grid simplified back by bending energy; slower)",
       {}}};
  return parameters;
}

}  // namespace meshprep
