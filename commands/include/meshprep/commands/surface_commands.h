#pragma once
/// \file surface_commands.h
/// The work of `meshprep smooth`, `enhance`, `repair` and `reconstruct` (outcome.h); simplify has
/// its own file (simplify_command.h).

#include "meshprep/commands/outcome.h"
#include "meshprep/core/io.h"
#include "meshprep/preprocess/enhance/enhance.h"
#include "meshprep/preprocess/reconstruct/reconstruct.h"
#include "meshprep/preprocess/repair/repair.h"
#include "meshprep/preprocess/smooth/smooth.h"
#include "meshprep/quality/report.h"

#include <optional>

namespace meshprep {

struct SmoothCommand {
  SmoothParams params;
  QualityParams quality;  ///< the output's report (distance_samples)
};

struct SmoothOutcome : SurfaceOutcome {
  SmoothResult result;
  QualityReport quality;  ///< of the surface, against the input
};

/// report: the stage's record, input_radius_ratio, input_self_intersections, quality (against the
/// input). \throws InvalidInput for a surface the halfedge mesh cannot hold; SolverError when the
/// output intersects itself more than the input.
SmoothOutcome smooth_command(LoadedMesh input, const SmoothCommand& command, const CommandNames& names,
                              const CommandHooks& hooks = {});

struct EnhanceCommand {
  EnhanceParams params;
  QualityParams quality;  ///< the output's report (distance_samples)
};

struct EnhanceOutcome : SurfaceOutcome {
  EnhanceResult result;
  QualityReport quality;  ///< of the surface, against the reference
};

/// Enhances `input` against `reference` (its own copy when null; names.input names it, or
/// `reference_name` when given). report: reference, faces_before, faces_after, the stage's
/// record, quality (against the reference).
EnhanceOutcome enhance_command(LoadedMesh input, const TriangleSoup* reference, const std::string& reference_name,
                               const EnhanceCommand& command, const CommandNames& names, const CommandHooks& hooks = {});

struct RepairOutcome : SurfaceOutcome {
  RepairResult result;
};

/// Repairs `input`. report: faces, vertices, the stage's record, readiness.
/// \throws SolverError when what is left is not closed, manifold and free of self-intersections.
RepairOutcome repair_command(TriangleSoup input, const RepairParams& params, const CommandNames& names,
                             const CommandHooks& hooks = {});

/// "welded 28 vertices, removed 0 degenerate and 1 duplicate faces, ...": what the repair did.
std::string repair_summary(const RepairResult& result);

struct ReconstructCommand {
  ReconstructParams params;
  bool adaptive = false;  ///< vertices placed by local features (adaptive_reconstruction.h)
};

struct ReconstructOutcome : SurfaceOutcome {
  ReconstructResult result;  ///< its mesh moved to `surface`; vertex_variation is the PLY's per-vertex scalar
};

/// Reconstructs a surface from `points`. report: points, the stage's record (with "adaptive").
/// \throws SolverError when every triangle is left out over gaps.
ReconstructOutcome reconstruct_command(const std::vector<Vec3>& points, const ReconstructCommand& command,
                                       const CommandNames& names, const CommandHooks& hooks = {});

}  // namespace meshprep
