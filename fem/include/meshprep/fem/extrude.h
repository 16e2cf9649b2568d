#pragma once
/// \file extrude.h
/// Closing an open height-field surface (terrain) into a solid block: the surface on top,
/// vertical side walls along its boundary, a flat base DEPTH below its lowest point.

#include "meshprep/core/mesh.h"
#include "meshprep/fem/tetrahedralize.h"

namespace meshprep {

/// Boundary tags of the extruded block, named "top", "sides" and "bottom". A surface that has two
/// patches or more keeps them on top; the sides and the bottom then take the next two tags.
enum ExtrudedTag : int { kTopTag = 1, kSideTag = 2, kBaseTag = 3 };

/// Up is the coordinate axis nearest to the surface's area-weighted mean normal (so that the base
/// and the walls are exactly planar). The surface must be a height field over that axis (every
/// face normal points up) with exactly one boundary loop.
/// Side walls are quads (planar facets), the base one polygon; TetGen triangulates them.
/// \param depth distance from the lowest surface point to the base, > 0 (absolute units).
/// \throws InvalidInput if the surface is closed, has several boundary loops, is not manifold or
///         folds over (not a height field).
SurfacePlc extrude_to_block(const TriangleSoup& surface, double depth);

}  // namespace meshprep
