#pragma once
// What the two VTK writers (export_vtu.cpp, export_vtk.cpp) store alike: tets as VTK_TETRA (or
// VTK_QUADRATIC_TETRA: the corners, then the mid-edge nodes of edges (0,1) (1,2) (2,0) (0,3) (1,3)
// (2,3), kTetEdges' order, vtkQuadraticTetra's documentation), and each tet's quality
// (tet_quality.h) as Float32 cell data for ParaView's colour maps and thresholds. Float32 holds
// an angle to 1e-5 degree and a ratio to 6e-8 relative, more than a colour map or a threshold
// tells apart, in half the bytes (and less than half the text) of Float64.

#include "meshprep/fem/tet_quality.h"

#include <cmath>
#include <cstdint>

namespace meshprep::detail {

inline constexpr int kVtkTetra = 10;
inline constexpr int kVtkTriangle = 5;
inline constexpr int kVtkQuadraticTetra = 24;
inline constexpr int kVtkQuadraticTriangle = 22;

inline int vtk_tet_type(const TetMesh& mesh) { return mesh.quadratic() ? kVtkQuadraticTetra : kVtkTetra; }

/// One Float64 cell array per tet quality measure.
struct VtkQualityArray {
  const char* name;
  double TetShape::*field;
};

inline constexpr VtkQualityArray kVtkQualityArrays[] = {{"min_dihedral_deg", &TetShape::min_dihedral_deg},
                                                        {"max_dihedral_deg", &TetShape::max_dihedral_deg},
                                                        {"radius_edge_ratio", &TetShape::radius_edge_ratio},
                                                        {"scaled_jacobian", &TetShape::scaled_jacobian}};

/// A quality value as VTK files hold it. VTK's ASCII readers parse numbers with operator>>, which
/// does not read "inf": a flat tet's radius-edge ratio (+inf) becomes Verdict's VERDICT_DBL_MAX,
/// 1e30, which it also uses for metrics that do not exist; so does any value beyond it.
inline float vtk_cell_value(double value) {
  constexpr double kVerdictMax = 1e30;
  return std::isfinite(value) && std::abs(value) < kVerdictMax ? static_cast<float>(value)
                                                                : static_cast<float>(std::copysign(kVerdictMax, value));
}

}  // namespace meshprep::detail
