#pragma once
/// \file patch_table.h
/// The boundary patches of a surface measured: one row per patch, for the report and the
/// `patches` command.

#include "meshprep/core/mesh.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace meshprep {

struct PatchRow {
  int tag = 0;
  std::string name;
  std::size_t faces = 0;
  double area = 0;
  /// The largest angle (degrees) between a face's normal and the patch's area-weighted mean
  /// normal: 0 for a plane, 90 for a cylinder's side; faces without area are left out.
  double normal_spread_deg = 0;
};

/// A row per tag of surface.patches, ascending; empty when the surface has none.
std::vector<PatchRow> patch_table(const TriangleSoup& surface);

nlohmann::ordered_json to_json(const std::vector<PatchRow>& table);

}  // namespace meshprep
