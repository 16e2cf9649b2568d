#pragma once
/// \file enhance_parameters.h
/// EnhanceParams' user-facing fields as the command line and the configuration file name them
/// (core/parameter.h): their keys, flags, ranges and meanings. The defaults are EnhanceParams'.

#include "meshprep/core/parameter.h"
#include "meshprep/preprocess/enhance/enhance.h"

namespace meshprep {

struct EnhanceParameters {
  ParameterInfo iterations, max_deviation, target_min_angle_deg, feature_angle_deg, flips, remesh, max_faces,
      time_limit_seconds;
};

const EnhanceParameters& enhance_parameters();

/// auto, on, off.
const Choices<EnhanceRemesh>& enhance_remesh_modes();

}  // namespace meshprep
