#pragma once
// The features RBF smoothing keeps (smooth.h): face normals denoised by bilateral filtering, and
// the crease edges found on them.

#include "meshprep/core/mesh.h"

#include <vector>

namespace meshprep::detail {

/// Face normals denoised by bilateral filtering (Zheng, Fu, Au and Tai 2011), indexed by face:
/// each normal becomes the mean of the normals of the faces around it (sharing a vertex), weighted
/// by area, by a Gaussian of the centroid distance (sigma: the mean edge length) and by a Gaussian
/// of the normal difference (sigma 0.35, about 20 degrees), 5 rounds, so that noise averages out
/// while the normals on the two sides of a crease do not mix.
std::vector<Vec3> filtered_face_normals(const TriMesh& mesh);

/// The crease edges (1, indexed by edge): interior edges whose faces' normals have a cosine under
/// `cos_limit`, and the borders between patches (mesh_patches.h).
std::vector<char> crease_edges(const TriMesh& mesh, const std::vector<Vec3>& normals, double cos_limit);

}  // namespace meshprep::detail
