#pragma once
// Moving vertices along their normals so the mesh fits the original surface in the least-squares
// sense: the distance energy of Hoppe et al. 1993 ("Mesh optimization"), restricted to the normal
// so the tangential layout (the triangle shapes) is left alone.

#include "shared/triangle_angles.h"

#include "meshprep/core/mesh.h"
#include "meshprep/quality/triangle_bvh.h"

#include <cstddef>
#include <vector>

namespace meshprep::detail {

/// One Gauss-Seidel sweep over the interior manifold vertices. Vertex v with unit normal n moves by
/// t n, t = -sum_s w_s n.(p_s - c_s) / sum_s w_s^2, the least-squares step for sample points p_s of
/// its faces (v itself with w = 1, the face centroids with w = 1/3, the points (2/3, 1/6, 1/6)
/// with w = 2/3), c_s the closest point of `reference` to p_s and w_s the barycentric weight of v
/// at p_s. The step is capped at a quarter of the shortest edge at v and refused if a face would
/// turn by more than 30 degrees or a smallest angle would drop below min(the angle whose cosine is
/// `min_angle_cosine`, its value before) or a face turn away from `field`'s up direction. Only vertices flagged in `movable` (by vertex index) are
/// fitted when it is given. Returns the number of vertices moved.
std::size_t fit_to_reference(TriMesh& mesh, const TriangleBvh& reference, double min_angle_cosine,
                             const HeightField& field, const std::vector<char>* movable = nullptr);

}  // namespace meshprep::detail
