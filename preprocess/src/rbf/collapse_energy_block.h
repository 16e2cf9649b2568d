#pragma once
// The three entries of the volume spline's bending-energy matrix that an edge collapse needs,
// computed without heap allocation for the small centre sets of a mesh (the union of two 1-rings).

#include "meshprep/core/mesh.h"

namespace meshprep::detail {

/// Largest centre set the fixed-size kernel takes; larger sets use volume_spline_energy_matrix.
constexpr int kMaxBlockCentres = 40;

/// E_aa, E_ab, E_bb of E = volume_spline_energy_matrix(centres) (thin_plate_spline.h).
struct EnergyBlock {
  double aa = 0, ab = 0, bb = 0;
};

/// Entries a and b of E = -8 pi M / scale, M the upper-left block of the inverse of the doubly
/// bordered matrix of eq. (2) on the unit-size centres (thin_plate_spline.h), through the null
/// space of its border: one Cholesky of size n - 4 (or n - 3 for coplanar centres).
/// \throws InvalidInput if n is outside [4, kMaxBlockCentres], two centres coincide or all are
///         collinear; SolverError if the bordered matrix is singular.
EnergyBlock collapse_energy_block(const Vec3* centres, int n, int a, int b);

}  // namespace meshprep::detail
