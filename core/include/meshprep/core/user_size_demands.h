#pragma once
/// \file user_size_demands.h
/// The demands the user's size settings make on a surface (core/size_field.h): a named patch's
/// size over its faces, the regions', and, for tets no remeshing prepared, the field of the
/// user's sizes alone over the surface's own density.

#include "meshprep/core/mesh.h"
#include "meshprep/core/size_field.h"

#include <memory>
#include <vector>

namespace meshprep {

/// The demands of the user's patch sizes on `surface`: over each face of a patch that has a size,
/// points no farther apart than half that size (the face cut into quarters until its pieces are
/// no longer), so that the field is within (1 + (G - 1) / 4) of it anywhere on the face.
/// \throws InvalidInput "size: no patch named 'X' (the surface's patches: a, b)" for a name the
/// surface does not have.
std::vector<SizeDemand> patch_size_demands(const SizeParams& params, const TriangleSoup& surface, double diagonal);
/// The user's regions with their sizes resolved against `diagonal`.
std::vector<RegionDemand> region_demands(const SizeParams& params, double diagonal);
/// The user's smallest patch or region size (infinity without any).
double smallest_local_size(const SizeParams& params, double diagonal);

/// The user's sizes alone, with no curvature or thickness demands of the surface (the tets of a
/// surface no remeshing followed): h = the size, else the surface's own density (at each face's
/// centroid the mean of its edges, graded into the volume: Gmsh's default), at most size_max,
/// refined on the patches and regions that have a size of their own, at least size_min; lengths
/// resolved against `surface`'s bounding-box diagonal. Null when the user set none of these.
std::shared_ptr<const SizeField> user_size_field(const SizeParams& params, const TriangleSoup& surface);

}  // namespace meshprep
