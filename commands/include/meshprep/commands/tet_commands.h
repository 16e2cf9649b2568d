#pragma once
/// \file tet_commands.h
/// The work of `meshprep tetrahedralize` and `improve` (outcome.h): TetGen on a surface, the tet
/// improvement, second-order tets, the quality and the FEM verdict of what is left.

#include "meshprep/commands/outcome.h"
#include "meshprep/fem/fem_verdict.h"
#include "meshprep/fem/improve_tets.h"
#include "meshprep/fem/quadratic.h"
#include "meshprep/fem/readiness.h"
#include "meshprep/fem/tet_mesh.h"
#include "meshprep/fem/tet_quality.h"
#include "meshprep/fem/tetrahedralize.h"
#include "meshprep/preprocess/patches/patches.h"

#include <optional>
#include <string>

namespace meshprep {

/// The tets a command made and what it measured. `failure` non-empty: the work could not be done
/// (the surface is not FEM-ready, or TetGen failed), `tets` is empty and `report` holds the
/// figures so far; the front end reports them and fails.
struct TetOutcome {
  TetMesh tets;
  nlohmann::ordered_json report = nlohmann::ordered_json::object();
  CommandMessages messages;
  std::string failure;
  std::optional<Readiness> readiness;  ///< of the surface (tetrahedralize, unless extruded)
  std::optional<ImproveResult> improvement;
  std::optional<QuadraticResult> second_order;
  /// Of the tets before the improvement: TetGen's (tetrahedralize, when improved), those read (improve).
  std::optional<TetQualityReport> quality_before;
  TetQualityReport quality;  ///< of the final tets
  TetVerdict verdict;        ///< of the final tets
  bool fem_ready() const { return failure.empty() && verdict.ok(); }
};

/// What to do after the tets are made (tetrahedralize) or read (improve).
struct TetFinishing {
  bool improve = true;  ///< tetrahedralize only: improve_tets on TetGen's tets (improve always does)
  ImproveParams improve_params;
  ElementOrderParams element_order;  ///< 2: make_quadratic on the final tets
  TetThresholds thresholds;          ///< the verdict's
};

struct TetrahedralizeCommand {
  TetParams params;
  TetFinishing finishing;
  PatchParams patches;  ///< the boundary patches the tets' boundary tags come from
  /// The tets follow the user's sizes (user_size_field: no curvature or thickness of their own;
  /// the surface is not remeshed: `enhance --size` first, or the pipeline, does that).
  SizeParams size;
  /// An open height field is closed into a block with a base this far below it: absolute if > 0,
  /// else this fraction of the bounding-box diagonal if > 0; 0 and 0: the surface must be closed.
  double extrude_depth = 0, extrude_relative = 0;
  bool fem_check = false;  ///< a P1 Poisson solve on the linear tets (fem_check.h)
};

/// Tetrahedralises `surface`. report: order, patches, readiness (or extrude_base_depth),
/// switches, tetgen_seconds, tetgen_quality and improvement (when improved), volume_change_relative,
/// fem_check, second_order, tet_quality, fem_ready, thresholds. `hooks.step` hears each long step.
/// \throws InvalidInput for bad parameters or patch edits; SolverError for an extrusion that cannot be made
///         and for flat tets; Cancelled when hooks.cancelled says so.
TetOutcome tetrahedralize_command(const TriangleSoup& surface, const TetrahedralizeCommand& command,
                                  const CommandNames& names, const CommandHooks& hooks = {});

/// Improves `tets` (and makes them second-order onto `reference`, or their own boundary when it
/// is null). report: order, tet_quality_before, improvement, second_order, tet_quality, fem_ready,
/// thresholds. \throws InvalidInput for tets that overlap; SolverError for flat tets.
TetOutcome improve_command(TetMesh tets, const TriangleSoup* reference, const TetFinishing& finishing,
                           const CommandNames& names, const CommandHooks& hooks = {});

/// Makes linear `tets` second-order (make_quadratic) onto `reference`, or onto the tets' own
/// boundary when it is null (then every boundary node stays on its flat face); report["second_order"]
/// gets the figures (quadratic.h's to_json), `messages` the edges kept straight.
QuadraticResult make_second_order(TetMesh& tets, const TriangleSoup* reference, nlohmann::ordered_json& report,
                                  CommandMessages& messages, const CommandHooks& hooks = {});

/// "smallest dihedral 2.29 -> 14.9 deg, largest 175 -> 159 deg (no gain, 0.04 s)" and, when the
/// surface caps the smallest angle below the goal, where.
std::string improvement_summary(const ImproveResult& result);

/// "1234 of 2000 boundary edges curved, 761 on the surface already, 5 left straight (3 would fold
/// a tet, 2 off the surface), smallest scaled Jacobian 0.41".
std::string second_order_summary(const QuadraticResult& result);

}  // namespace meshprep
