#pragma once
/// \file repair_parameters.h
/// RepairParams' user-facing fields as the command line names them (core/parameter.h). The
/// defaults are RepairParams'.

#include "meshprep/core/parameter.h"

namespace meshprep {

struct RepairParameters {
  ParameterInfo weld_tolerance;
  ParameterInfo max_hole;
  ParameterInfo keep_cavities;
};

const RepairParameters& repair_parameters();

}  // namespace meshprep
