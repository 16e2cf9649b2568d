#pragma once
/// \file fem_parameters.h
/// The user-facing fields of TetParams, ImproveParams, TetThresholds and ElementOrderParams as the
/// command line and the configuration file name them (core/parameter.h): keys, flags, ranges and
/// meanings. The defaults are those structs' own.

#include "meshprep/core/parameter.h"

namespace meshprep {

struct TetParameters {
  ParameterInfo radius_edge, min_dihedral_deg, max_volume_relative, keep_surface;
};
const TetParameters& tet_parameters();

struct ImproveParameters {
  ParameterInfo tet_quality, goal_min_dihedral_deg, goal_max_dihedral_deg, insertion, max_passes, boundary_deviation,
      time_limit_seconds;
};
const ImproveParameters& improve_parameters();

struct ElementOrderParameters {
  ParameterInfo order;
};
const ElementOrderParameters& element_order_parameters();

struct VerdictParameters {
  ParameterInfo min_dihedral_deg, max_dihedral_deg, max_inverted_tets;
};
const VerdictParameters& verdict_parameters();

}  // namespace meshprep
