#pragma once
// Smoothing of one free vertex: the position that maximises the worst quality of the vertex's
// tets (worst_tet_maximiser.h), kept only if every tet of the vertex stays positive by the exact
// orientation test.

#include "tet_complex.h"

namespace meshprep::improve {

/// Moves free vertex v where the worst of its tets is better; true if it moved.
/// \pre mesh.free_vertex(v).
bool smooth_vertex(TetComplex& mesh, VertexId v);

}  // namespace meshprep::improve
