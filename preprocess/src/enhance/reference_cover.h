#pragma once
// Whether a local change of the mesh leaves the reference surface under it covered: the test that
// keeps collapses and the remeshing's moves from cutting a corner or a ridge off the part.

#include "enhance/surface_constraints.h"

#include "meshprep/core/mesh.h"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace meshprep::detail {

using Corners = std::array<Vec3, 3>;

/// Per face of the reference, which of its edges (edge k joins corners k and k + 1) are bent: its
/// two faces' normals more than 0.1 degrees apart (or it borders only one face). Only along such
/// an edge can a chord between two points of the surface leave it.
std::vector<std::uint8_t> bent_reference_edges(const SoupView& reference);

/// The points of the reference the enhancement keeps covered (move_guards.h): its vertices, then,
/// with `spacing` > 0, points along each bent edge at most `spacing` apart (a chord can cut a
/// ridge between two far-apart vertices of a CAD part).
std::vector<Vec3> reference_probes(const SoupView& reference, double spacing);

/// Whether replacing a patch of faces (`before`, bounded by the `rim` segments) by `after` (the
/// same rim) keeps every reference vertex under the patch within max(limit, its distance before),
/// and, given `bent` (bent_reference_edges), every point along the bent reference edges under it
/// (sampled at an eighth of the patch's size). The new faces' own points can all lie on the
/// reference while the reference is uncovered: a chord across a faceted cylinder's strips
/// (fandisk) leaves the strip line between them 1.6 times the bound away. A point nearer the rim
/// than the patch's inside belongs to the faces beyond the rim and is not asked.
bool keeps_reference_covered(const SurfaceConstraints& constraints, const std::vector<Corners>& before,
                             const std::vector<Corners>& after, const std::vector<std::pair<Vec3, Vec3>>& rim,
                             double limit, const std::vector<std::uint8_t>* bent = nullptr);

}  // namespace meshprep::detail
