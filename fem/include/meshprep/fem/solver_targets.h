#pragma once
/// \file solver_targets.h
/// Which file a solver reads: `--target NAME` picks the format, the Gmsh version and the tag
/// encoding for it.
///
/// | target | file | why |
/// | --- | --- | --- |
/// | mfem | .msh 2.2 ASCII | MFEM's Gmsh reader takes only 2.2; physical tags become attributes (>= 1) |
/// | fenicsx | .msh 4.1 | dolfinx.io.gmshio reads 4.1; physical groups become cell/facet tags |
/// | dealii | .msh 2.2 ASCII | GridIn::read_msh without the Gmsh API; physical tags become material/boundary ids |
/// | calculix | .inp | C3D4 elements, ELSET per region, NSET, ELSET and element-face SURFACE per boundary tag (named by its patch) |
/// | code_aster | .msh 2.2 ASCII | read with PRE_GMSH; physical groups become GROUP_MA |

#include "meshprep/fem/export.h"

#include <string>
#include <vector>

namespace meshprep {

struct SolverTarget {
  std::string name;
  std::string extension;  ///< with the dot
  TetExportOptions options;
};

const std::vector<SolverTarget>& solver_targets();

/// \throws InvalidInput naming the valid targets.
const SolverTarget& find_solver_target(const std::string& name);

}  // namespace meshprep
