#pragma once
// Creases: the runs of sharp edges that bound a part's faces. One definition for the enhancement
// (whose features they are) and the segmentation into boundary patches (whose borders they are).

#include "meshprep/core/mesh.h"

#include <cmath>
#include <vector>

namespace meshprep::detail {

/// A run turns by less than 30 degrees at each of its vertices.
inline const double kStraightCosine = std::cos(150.0 * M_PI / 180.0);

/// The other end of edge e from v.
TriMesh::VertexHandle other_end(const TriMesh& mesh, TriMesh::EdgeHandle e, TriMesh::VertexHandle v);

/// The edges marked in `feature` (one flag per edge) at each vertex.
std::vector<std::vector<TriMesh::EdgeHandle>> incident(const TriMesh& mesh, const std::vector<char>& feature);

/// A vertex where a run of sharp edges goes straight on: exactly two of them, nearly opposite.
/// (`cosine`: of the smallest angle between the two edges that still counts as straight on.)
bool straight_through(const TriMesh& mesh, TriMesh::VertexHandle v, const std::vector<TriMesh::EdgeHandle>& edges,
                      double cosine = kStraightCosine);

/// One flag per edge: the sharp interior edges (dihedral angle beyond the feature angle, whose
/// cosine is `cos_feature`) that belong to a run at least five median edge lengths long: isolated
/// sharp edges of a scan's noise are no feature, a CAD part's long straight edge is even when
/// simplification left it only two or three edges (fandisk after CGAL's decimation). With
/// `between_planes`, also those whose two faces each have a neighbour in their plane: a CAD
/// tessellation's edge between two planes (a box of twelve triangles has runs of one edge; a
/// scan's faces almost never have such neighbours: 0.5 % of the femur's edges are flat).
std::vector<char> creases(const TriMesh& mesh, double cos_feature, bool between_planes);

}  // namespace meshprep::detail
