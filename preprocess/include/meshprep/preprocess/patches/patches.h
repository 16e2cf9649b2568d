#pragma once
/// \file patches.h
/// Boundary patches: the named sets of faces where a solver fixes, loads or heats a part
/// (TriangleSoup::patches, mesh_patches.h). A surface whose file names none is segmented into the
/// regions its creases bound: the enhancement's own creases (shared/creases.h: runs of edges
/// sharper than the feature angle, at least five median edges long, or between two planes of a
/// CAD tessellation), so that each patch border is a feature every later stage keeps. A smooth
/// scan is one patch; a box six; a cylinder three. Patches are named patch_1, patch_2, ... in
/// order of decreasing area. Then renames and merges the user asked for are applied.

#include "meshprep/core/mesh.h"
#include "meshprep/core/patch_names.h"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace meshprep {

/// The enhancement's default crease angle, and so the patches' (EnhanceParams::feature_angle_deg).
inline constexpr double kDefaultCreaseAngleDeg = 45;

struct PatchParams {
  /// An edge with a larger dihedral angle (degrees) may border a patch. Unset: kDefaultCreaseAngleDeg
  /// (the pipeline passes its enhancement's angle, so that borders and creases are the same edges).
  std::optional<double> feature_angle_deg;
  /// Segment even when the file names patches (its names are then dropped).
  bool resegment = false;
  /// OLD=NEW pairs, applied in order after the merges.
  std::vector<std::pair<std::string, std::string>> renames;
  /// Each a list of names: the faces of all of them join the first.
  std::vector<std::vector<std::string>> merges;
};

struct PatchResult {
  bool segmented = false;            ///< the patches were found from the creases (else the file named them)
  double feature_angle_deg = 0;      ///< the angle used when segmenting
  std::size_t patches = 0;           ///< patches after the edits
  std::vector<RenamedTag> renamed;   ///< names changed: the user's renames, and names made to follow the rule
  std::size_t merged = 0;            ///< patches merged into another
};

/// Segments `surface` unless it has patches (or `params.resegment`), then applies the merges and
/// renames. The surface must be manifold (every face in one halfedge mesh).
/// \throws InvalidInput for a feature angle outside [0, 180), a non-manifold surface, a rename or
///         merge naming a patch the surface does not have (the message lists those it has), or
///         a merge of fewer than two names.
PatchResult find_patches(TriangleSoup& surface, const PatchParams& params);

/// Checks the edits against the patches of `names` alone (no surface), as find_patches would:
/// the command line and the pipeline refuse a rename of an unknown patch before any other work.
/// \throws InvalidInput as find_patches.
void check_patch_edits(const TagNames& names, const PatchParams& params);

nlohmann::ordered_json to_json(const PatchResult& result);

}  // namespace meshprep
