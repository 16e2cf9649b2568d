#pragma once
/// \file coincident_vertices.h
/// Seams of separate vertices at exactly one place: a file that splits its vertices (VTK's
/// vtkPolyDataNormals writes one per face corner along creases, some exporters one per face). The
/// faces around them are not connected, so the surface looks open along every such seam and its
/// touching faces look like intersections; the readiness check and the pipeline name this first.
/// Only border vertices (on an edge of one face) count: two closed bodies that touch at shared
/// corners are not split, and welding them would only pinch them together.

#include "meshprep/core/mesh.h"

#include <cstddef>
#include <vector>

namespace meshprep {

struct CoincidentVertices {
  std::size_t merged = 0;           ///< border vertices that lie exactly on a border vertex of smaller index
  std::vector<std::size_t> faces;   ///< the faces with a corner at such a place
  TriangleSoup welded;              ///< the soup with each place's vertices made one; empty when merged == 0
};

CoincidentVertices find_coincident_vertices(const TriangleSoup& surface);

}  // namespace meshprep
