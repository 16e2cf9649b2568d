#pragma once
/// \file tet_mesh_report.h
/// The report of `meshprep quality` on a tetrahedral mesh (outcome.h): what the file held beyond
/// the mesh, the tets' quality (analyze_tet_quality, as its to_json gives it) and the topology of
/// the boundary (the faces of one tet).

#include "meshprep/fem/import.h"
#include "meshprep/fem/tet_mesh.h"

#include <nlohmann/json.hpp>

namespace meshprep {

/// {"file", "input": {format, counts of TetReadReport}, "tet_quality": to_json(analyze_tet_quality),
///  "boundary": {faces, interface_faces, internal_faces, faces_per_tag, faces_per_patch (by name:
///  the mesh's boundary_names, `boundary_<t>` for a tag without one, as the writers name it),
///  closed, manifold, oriented, components, non_manifold_edges, non_manifold_vertices, genus}}.
nlohmann::ordered_json tet_mesh_report(const TetMesh& mesh, const TetReadReport& read);

}  // namespace meshprep
