#pragma once
// Garland-Heckbert error quadrics as the simplifier's memory of the original surface: each vertex
// carries the sum of the (area-weighted) planes of the original faces it stands for.

#include "meshprep/core/mesh.h"

#include <OpenMesh/Core/Geometry/QuadricT.hh>

#include <vector>

namespace meshprep::detail {

using Quadric = OpenMesh::Geometry::QuadricT<double>;

/// Per vertex (indexed by vertex index): sum over incident faces of area / unit_length^2 times the
/// squared distance to the face's plane, plus, at boundary edges, a heavily weighted plane through
/// the edge perpendicular to its face, so boundary vertices stay on the boundary curve.
std::vector<Quadric> vertex_quadrics(const TriMesh& mesh, double unit_length);

/// Q(p).
double evaluate(const Quadric& q, const Vec3& p);

/// The quadric's RMS distance estimate at p: sqrt(Q(p) / total weight of its planes).
double rms_plane_distance(const Quadric& q, const Vec3& p);

/// The point minimising Q nearest to `anchor` (pseudo-inverse of the 3x3 part with eigenvalues
/// below 1e-3 of the largest dropped, as Lindstrom 2000): on a flat patch the anchor moved onto
/// the plane, on a crease the nearest point of the crease line, at a corner the corner.
Vec3 minimiser_near(const Quadric& q, const Vec3& anchor);

}  // namespace meshprep::detail
