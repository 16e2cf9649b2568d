#pragma once
/// \file surface_variation.h
/// The paper's surface variation, its "curvature analysis" of a surface (Sections 3 and 4; the
/// measure of Pauly, Gross and Kobbelt 2002): for the covariance matrix C = sum (p - c)(p - c)^T of a
/// neighbourhood about its centroid c, with eigenvalues lambda1 <= lambda2 <= lambda3,
///
///     sigma = lambda1 / (lambda1 + lambda2 + lambda3),
///
/// 0 where the neighbourhood is planar, growing with curvature, at most 1/3 (isotropic scatter).

#include "meshprep/core/mesh.h"

#include <vector>

namespace meshprep {

/// Surface variation sigma of every point of `soup`, over the point's 2-ring: the point itself
/// and the points within two edges of it along the soup's triangles (a repeated-index triangle
/// contributes its distinct edges). A point whose 2-ring has fewer than 3 points (an isolated
/// point, say) or a zero covariance gets 0.
/// \pre every index of soup.triangles is < soup.points.size() (the TriangleSoup invariant).
/// \return one value per soup point, in point order, each in [0, 1/3].
std::vector<double> surface_variation(const TriangleSoup& soup);

}  // namespace meshprep
