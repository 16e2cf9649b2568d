#pragma once
/// \file quality_parameters.h
/// QualityParams' user-facing field as the command line and the configuration file name it
/// (core/parameter.h). The default is QualityParams'.

#include "meshprep/core/parameter.h"

namespace meshprep {

struct QualityParameters {
  ParameterInfo distance_samples;
};

const QualityParameters& quality_parameters();

}  // namespace meshprep
