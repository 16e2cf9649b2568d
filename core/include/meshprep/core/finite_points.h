#pragma once
/// \file finite_points.h
/// A stage's last check on its own output. A non-finite coordinate coming out of a stage is that
/// stage's failure (a degenerate local frame or fit), never the input's: it must be reported as
/// the stage's, and must never reach a file.

#include "meshprep/core/mesh.h"

#include <string>

namespace meshprep {

/// \throws SolverError "<stage> failed: vertex N has a non-finite coordinate (...)" for the first
///         vertex with a NaN or infinite coordinate.
void require_finite_points(const TriMesh& mesh, const std::string& stage);
void require_finite_points(const std::vector<Vec3>& points, const std::string& stage);

}  // namespace meshprep
