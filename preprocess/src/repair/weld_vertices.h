#pragma once
// Repair steps 1 and 2 (repair.h): welding, and the faces and vertices it leaves without use.

#include "meshprep/core/mesh.h"

#include <cstddef>
#include <vector>

namespace meshprep::detail {

struct WeldCounts {
  std::size_t welded_vertices = 0, degenerate_faces = 0, duplicate_faces = 0, unused_vertices = 0;
  /// With WeldScope::open_edges: once the exact copies were joined, no edge had one face alone.
  bool input_closed = false;
};

/// Which vertices are welded within the distance: all, or (the repair's first step) those on an
/// edge that one face alone uses once the exact copies are joined - the seams of a file that
/// splits its vertices. Exact copies are joined everywhere in both. A closed part is thus never
/// welded across a thin wall (a sheet thinner than the distance would lose both sides).
enum class WeldScope { everywhere, open_edges };

/// Welds vertices within `distance` of each other (each cluster onto its lowest index, which does
/// not move; `scope` says which), then removes faces naming a vertex twice and faces repeating
/// another's vertices (all copies of faces on the same vertices facing both ways whose edges have
/// two other faces each, in a region of such faces that other faces meet: a wall two solids
/// share; of a part written double-sided, the first copy of each face stays), and drops the
/// vertices no face uses.
WeldCounts weld_vertices(TriangleSoup& soup, double distance, WeldScope scope = WeldScope::everywhere);

/// Removes the faces `removed` flags (one flag per face), their patches with them.
void remove_faces(TriangleSoup& soup, const std::vector<char>& removed);

/// Drops the vertices no face uses; the others keep their order (a surface with none comes out as
/// it went in, numbering included). Returns how many were dropped.
std::size_t drop_unused_vertices(TriangleSoup& soup);

}  // namespace meshprep::detail
