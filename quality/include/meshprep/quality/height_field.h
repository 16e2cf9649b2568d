#pragma once
/// \file height_field.h
/// Whether an open surface is a height field over a coordinate axis: what a terrain must stay for
/// extrude_to_block (fem/extrude.h) to close it into a block, and what simplify keeps.

#include "meshprep/core/mesh.h"

#include <cstddef>
#include <optional>

namespace meshprep {

/// The signed coordinate axis nearest to the surface's area-weighted mean normal (an axis keeps a
/// block's base and walls exactly planar); std::nullopt when the surface has no area.
std::optional<Vec3> mean_normal_axis(const TriangleSoup& surface);

/// The first face whose normal does not point along `up` (a fold of the height field).
std::optional<std::size_t> first_fold(const TriangleSoup& surface, const Vec3& up);

/// mean_normal_axis when no face folds over it: the surface is a height field over that axis.
std::optional<Vec3> height_field_up(const TriangleSoup& surface);

}  // namespace meshprep
