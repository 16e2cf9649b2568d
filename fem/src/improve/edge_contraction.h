#pragma once
// Edge contraction (one of the operations of Klingner & Shewchuk's schedule, IMR 2007): a free
// vertex u is merged into a neighbour w; the tets with the edge uw disappear and the other tets
// of u take w in u's place. It removes a vertex that no position suits (crowded among others,
// or squeezed against the boundary), which smoothing cannot do and insertion only makes worse.

#include "tet_complex.h"
#include "topological_moves.h"

namespace meshprep::improve {

/// The contraction of free vertex u onto the neighbour that gives the best worst tet: the move
/// replaces the tets of u (no fresh tets when u has none). \pre mesh.free_vertex(u).
Move best_contraction(const TetComplex& mesh, VertexId u);

}  // namespace meshprep::improve
