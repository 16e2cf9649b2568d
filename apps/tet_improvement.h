#pragma once
// The tet improvement as the commands run it (tetrahedralize, improve): progress on a terminal,
// Ctrl-C stops it, its figures in the command's JSON.

#include "meshprep/fem/improve_tets.h"
#include "meshprep/fem/tet_mesh.h"

#include <nlohmann/json.hpp>

#include <string>

namespace meshprep::cli {

/// Improves `tets`; json["improvement"] gets the figures, stderr (a terminal only) a line of
/// progress, stdout nothing. \throws Cancelled on Ctrl-C (the tets are then unchanged).
ImproveResult run_improvement(TetMesh& tets, const ImproveParams& params, nlohmann::ordered_json& json);

/// "smallest dihedral 2.29 -> 14.9 deg, largest 175 -> 159 deg (no gain, 0.04 s)" and, when the
/// surface caps the smallest angle below the goal, where.
std::string improvement_summary(const ImproveResult& result);

}  // namespace meshprep::cli
