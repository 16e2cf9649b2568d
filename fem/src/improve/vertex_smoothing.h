#pragma once
// Smoothing of one vertex, free or sliding on the boundary (boundary_slides.h): the position that
// maximises the worst quality of the vertex's tets (worst_tet_maximiser.h), kept only if every tet
// of the vertex stays positive by the exact orientation test.

#include "tet_complex.h"
#include "worst_tet_maximiser.h"

#include <functional>

namespace meshprep::improve {

/// Moves vertex v where the worst of its tets is better: the maximiser's position (on `constraint`
/// when given: a boundary vertex sliding on its surface), kept only if every tet of the vertex
/// stays positive by the exact orientation test and `acceptable` (when given) takes it; else moved
/// halfway back towards the start (onto the constraint) and tried again, at most `halvings` times.
/// True if it moved. \pre mesh.free_vertex(v), or a constraint that keeps the boundary's shape.
bool smooth_vertex(TetComplex& mesh, VertexId v, const SlideConstraint* constraint = nullptr,
                   const std::function<bool(const Vec3&)>& acceptable = {}, int halvings = 0);

}  // namespace meshprep::improve
