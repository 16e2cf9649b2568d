#pragma once
/// \file smooth_parameters.h
/// SmoothParams' user-facing fields as the command line and the configuration file name them
/// (core/parameter.h): their keys, flags, ranges and meanings. The defaults are SmoothParams'.

#include "meshprep/core/parameter.h"
#include "meshprep/preprocess/smooth/smooth.h"

namespace meshprep {

struct SmoothParameters {
  ParameterInfo method, iterations, neighbors, smoothing, relaxation, feature_angle_deg, adaptive, preserve_volume;
};

const SmoothParameters& smooth_parameters();

/// The names of SmoothMethod.
const Choices<SmoothMethod>& smooth_methods();

}  // namespace meshprep
