#pragma once
/// \file simplify_command.h
/// `meshprep simplify`'s work (outcome.h): the edge collapse, or the Figure 6 combination with the
/// enhancement, then the output's quality against the input.

#include "meshprep/commands/outcome.h"
#include "meshprep/core/io.h"
#include "meshprep/preprocess/simplify/simplify.h"
#include "meshprep/quality/report.h"

namespace meshprep {

struct SimplifyCommand {
  SimplifyParams params;  ///< keep_ratio or target_faces say how far
  /// Reduce in three stages, each followed by the enhancement against the input (simplify_and_enhance.h).
  bool enhance = false;
  QualityParams quality;  ///< the output's report (distance_samples)
};

struct SimplifyOutcome : SurfaceOutcome {
  SimplifyResult result;  ///< the reductions' (with enhance: all three)
  QualityReport quality;  ///< of the surface, against the input
};

/// report: cost, min_angle_deg, max_error, the stage's record, input_topology (closed, manifold,
/// genus, self_intersections), quality. \throws InvalidInput for a surface the halfedge mesh cannot
/// hold; SolverError when the output intersects itself more than the input.
SimplifyOutcome simplify_command(LoadedMesh input, const SimplifyCommand& command, const CommandNames& names,
                                const CommandHooks& hooks = {});

}  // namespace meshprep
