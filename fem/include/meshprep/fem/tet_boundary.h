#pragma once
/// \file tet_boundary.h
/// The boundary of a tetrahedral mesh, from its tets alone.

#include "meshprep/fem/tet_mesh.h"

#include <vector>

namespace meshprep {

/// The faces of exactly one tet, each oriented away from its tet (outward for positively
/// oriented tets), in tet order: the faces of tet t before those of tet t + 1, and within a tet
/// the face opposite corner 0 first. A face of more than two tets is no boundary face (such a mesh
/// is not valid; read_tet_mesh refuses it).
/// \pre every tet index is < mesh.points.size() and there are fewer than 2^30 tets.
std::vector<Triangle> tet_boundary(const TetMesh& mesh);

/// The boundary surface of `mesh` as a soup on the points its faces use (in point order): the
/// faces of tet_boundary, each with the tag mesh.boundary_faces gives it (1 if none) as its patch,
/// and mesh.boundary_names as the patches' names. A mesh whose boundary is all tag 1 without a
/// name has no patches. Interface faces (between two tets) are left out.
TriangleSoup boundary_surface(const TetMesh& mesh);

}  // namespace meshprep
