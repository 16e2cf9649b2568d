#pragma once
// A topological move followed by the smoothing of the free corners it touched, judged as one
// move: where a flip alone makes things worse but opens room for a vertex to move (a free vertex
// squeezed into a thin wedge between two boundary faces, whose tets a 2-3 flip joins into one
// and the vertex then leaves), neither step is kept alone by the hill climbing, both together
// are. The move is applied, the corners smoothed, and the whole kept only if the worst tet among
// all tets whose shape changed is better than the worst of those it replaced; otherwise the mesh
// is restored exactly: the points to their bits, then the old tets under their old ids.

#include "tet_complex.h"
#include "topological_moves.h"

#include <vector>

namespace meshprep::improve {

/// Tries `move` (valid for the current mesh) with the smoothing of its free corners; true if
/// kept, and then `changed` holds the tets whose quality changed. When not kept, the mesh is as
/// before, ids included.
bool move_and_smooth(TetComplex& mesh, const Move& move, std::vector<TetId>& changed);

}  // namespace meshprep::improve
