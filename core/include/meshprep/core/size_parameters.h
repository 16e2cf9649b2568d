#pragma once
/// \file size_parameters.h
/// SizeParams' user-facing fields as the command line and the configuration file name them
/// (core/parameter.h). The defaults are SizeParams'.

#include "meshprep/core/parameter.h"
#include "meshprep/core/size_field.h"

namespace meshprep {

struct SizeParameters {
  ParameterInfo size, size_min, size_max, grading, curvature_points, thickness_layers, patch_sizes, regions;
};

const SizeParameters& size_parameters();

/// \throws InvalidInput "size: <key> must be ..., not <value>" for a field out of its range,
/// size_min over size_max (when both are of one kind: absolute or relative), a patch size's name
/// that is no patch name (patch_names.h), or a region that is empty (a box's lo over its hi, a
/// ball's radius not positive) or not finite.
void check_size_params(const SizeParams& params);

}  // namespace meshprep
