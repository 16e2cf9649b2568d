#pragma once
// The shape guard of an edge collapse: what the faces around the edge may become.

#include "shared/triangle_angles.h"

#include "meshprep/core/mesh.h"

namespace meshprep::detail {

/// Whether the faces that survive the collapse of h (from the removed vertex to the kept one) with
/// the kept vertex at p stay well shaped: none may flip by more than 90 degrees, turn away from a
/// height field's up direction (`field`) or become degenerate, and their smallest angle may not
/// fall below min(the angle of `min_angle_cosine`, the smallest angle of the faces around the edge
/// before).
bool collapse_keeps_shape(const TriMesh& mesh, TriMesh::HalfedgeHandle h, const Vec3& p, double min_angle_cosine,
                          const HeightField& field);

}  // namespace meshprep::detail
