#pragma once
/// \file reconstruct_parameters.h
/// ReconstructParams' user-facing fields as the command line and the configuration file name them
/// (core/parameter.h): their keys, flags, ranges and meanings. The defaults are ReconstructParams'
/// and PartitionOfUnityParams'.

#include "meshprep/core/parameter.h"

namespace meshprep {

struct ReconstructParameters {
  ParameterInfo resolution, spacing, vertices, leaf_size, neighbors, variation_threshold, variation_growth, max_gap,
      fill_holes;
  /// compose/adaptive_reconstruction.h: reconstruct_adaptive instead of reconstruct_surface.
  ParameterInfo adaptive;
};

const ReconstructParameters& reconstruct_parameters();

}  // namespace meshprep
