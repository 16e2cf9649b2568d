#pragma once
/// \file prepare_plc.h
/// A surface made into TetGen's input, by the one policy `meshprep tetrahedralize` and the pipeline
/// share. Given a base depth, an open height field (a terrain) is closed into a block (extrude.h).
/// Otherwise the surface is checked (readiness.h); a ready surface enclosing negative volume is
/// flipped: TetGen does not mind, but the normals of the boundary tags do.

#include "meshprep/core/mesh.h"
#include "meshprep/fem/readiness.h"
#include "meshprep/fem/tetrahedralize.h"

#include <optional>
#include <string>

namespace meshprep {

struct PreparedPlc {
  std::optional<SurfacePlc> plc;          ///< empty: the surface cannot be tetrahedralised (below: why)
  std::optional<Readiness> readiness;     ///< the check, when the surface was not extruded
  bool flipped_inward = false;            ///< the surface enclosed negative volume and was flipped
  std::string extrusion_problem;          ///< why the block could not be made (extrude_to_block's message)
};

/// \param extrude_depth the base's distance below the lowest point (absolute units, > 0), or empty
///        to check the surface as a closed solid.
PreparedPlc prepare_plc(const TriangleSoup& surface, std::optional<double> extrude_depth);

}  // namespace meshprep
