#pragma once
/// \file simplify_parameters.h
/// SimplifyParams' user-facing fields as the command line and the configuration file name them
/// (core/parameter.h): their keys, flags, ranges and meanings. The defaults are SimplifyParams'.

#include "meshprep/core/parameter.h"
#include "meshprep/preprocess/simplify/simplify.h"

namespace meshprep {

struct SimplifyParameters {
  ParameterInfo keep_ratio, target_faces, cost, min_angle_deg, max_error, polish;
};

const SimplifyParameters& simplify_parameters();

/// The names of CollapseCost.
const Choices<CollapseCost>& collapse_costs();

}  // namespace meshprep
