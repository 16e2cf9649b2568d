#pragma once
/// \file repair_parameters.h
/// RepairParams' user-facing fields as the command line names them (core/parameter.h). The
/// defaults are RepairParams'.

#include "meshprep/core/parameter.h"
#include "meshprep/preprocess/repair/repair.h"

namespace meshprep {

struct RepairParameters {
  ParameterInfo weld_tolerance;
  ParameterInfo max_hole;
  ParameterInfo keep_cavities;
  ParameterInfo route;
  ParameterInfo envelope_cells;
  ParameterInfo time_limit_seconds;
};

const RepairParameters& repair_parameters();

/// The names of RepairRoute.
const Choices<RepairRoute>& repair_routes();

}  // namespace meshprep
