#pragma once
// The last shape step before the fit: tail vertices (vertex_relaxation.h) slide towards their
// 1-ring centroid on the original surface itself. The polish moves them within the quadrics'
// error estimate, which forbids most moves across curved CAD faces (a cylinder's planes are
// violated by any move around it); here the vertex stays on the exact surface, and the faces
// around it may not move farther from it.

#include "shared/triangle_angles.h"

#include "meshprep/core/mesh.h"
#include "meshprep/quality/triangle_bvh.h"

#include <cstddef>

namespace meshprep::detail {

/// One Gauss-Seidel sweep over the relaxable tail vertices not on a feature. Vertex v at x, with
/// unit normal n and offset t = n.(x - c(x)) from its closest point c(x) of `reference`, goes to
/// c(x + a (centroid - x)) + t n, the largest of a = 1, 1/2, 1/4, 1/8 for which: the target is
/// within a quarter of v's longest edge of the surface; no face turns by more than 60 degrees;
/// the largest radius ratio around v drops; no smallest angle falls below min(the angle whose
/// cosine is `min_angle_cosine`, its value before); and the faces' farthest sample from
/// `reference` (their centroids and the midpoints of v's edges) stays within max(`tolerance`,
/// its distance before); and no face turns away from `field`'s up direction. Returns the number
/// of vertices moved.
std::size_t relax_on_reference(TriMesh& mesh, const TriangleBvh& reference, double tolerance, double min_angle_cosine,
                               const HeightField& field);

}  // namespace meshprep::detail
