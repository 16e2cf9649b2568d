#pragma once
// Vertex insertion where flips and smoothing are stuck (Klingner & Shewchuk, IMR 2007): a new
// vertex inside the worst tet, joined to the boundary of a cavity of tets around it. The cavity
// starts as the tet itself and grows, one tet at a time, across its unconstrained boundary face
// whose new tet (the face joined to the new vertex) is worst; at every size the new vertex is
// placed where the worst of its new tets is best (worst_tet_maximiser.h), and of the cavities
// met on the way the one whose worst new tet is best is kept, if it beats the worst tet it
// replaces.

#include "tet_complex.h"

namespace meshprep::improve {

/// Inserts a vertex in or near tet t if that raises the worst quality of the tets it replaces;
/// true if it did. The new vertex is free and inside the mesh's space (never on a constrained
/// face); mesh.created() holds the new tets.
bool insert_vertex(TetComplex& mesh, TetId t, std::size_t max_cavity);

}  // namespace meshprep::improve
