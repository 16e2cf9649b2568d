#pragma once
/// \file patches_parameters.h
/// PatchParams' user-facing fields as the command line names them (core/parameter.h).

#include "meshprep/core/parameter.h"

namespace meshprep {

struct PatchParameters {
  ParameterInfo feature_angle_deg;
  ParameterInfo resegment;
  ParameterInfo renames;
  ParameterInfo merges;
};

const PatchParameters& patch_parameters();

}  // namespace meshprep
