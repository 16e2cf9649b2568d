#pragma once
/// \file size_parameters.h
/// SizeParams' user-facing fields as the command line and the configuration file name them
/// (core/parameter.h). The defaults are SizeParams'.

#include "meshprep/core/parameter.h"
#include "meshprep/core/size_field.h"

namespace meshprep {

struct SizeParameters {
  ParameterInfo size, size_min, size_max, grading, curvature_points, thickness_layers;
};

const SizeParameters& size_parameters();

/// \throws InvalidInput "size: <key> must be ..., not <value>" for a field out of its range, or
/// size_min over size_max (when both are of one kind: absolute or relative).
void check_size_params(const SizeParams& params);

}  // namespace meshprep
