#pragma once
/// \file simplify_and_enhance.h
/// The paper's Figure 6 combination of two stages: the reduction (simplify.h) runs in three steps
/// of equal ratio, each followed by the enhancement (enhance.h) against the input, so that the
/// later collapses start from well-shaped triangles.

#include "meshprep/core/mesh.h"
#include "meshprep/preprocess/enhance/enhance.h"
#include "meshprep/preprocess/simplify/simplify.h"

#include <cstddef>
#include <functional>

namespace meshprep {

struct SimplifyAndEnhanceParams {
  /// The target and the collapses. CollapseCost::Quadric (OpenMesh's baseline) is not run in
  /// steps: it reduces once and nothing is enhanced. Its progress is not called (`progress` is).
  SimplifyParams simplify;
  /// Each step's enhancement; its max_face_change is replaced: the steps share the 1 % slack of
  /// the target.
  EnhanceParams enhance;
  /// Called with each reduction's fraction done, then with s / 3 after step s, and 1 at the end.
  std::function<void(double)> progress;
};

struct SimplifyAndEnhanceResult {
  /// The reductions: faces before and after, the target and whether it was reached, the time of
  /// the whole (enhancements included), and the counters of collapses, rejections, energy
  /// evaluations, polish, fit and intersection retries summed over the steps (reshapes,
  /// stuck_restarts and banded_queue are not summed: 0 and false).
  SimplifyResult simplify;
  std::size_t stages = 0;            ///< enhancements run
  std::size_t rounds = 0;            ///< enhancement rounds kept, summed over the steps
  std::size_t flips = 0, removed_vertices = 0, split_edges = 0;  ///< the enhancements', summed
};

/// Simplify and enhance `mesh` in place (garbage-collected on return).
/// \throws InvalidInput as simplify() and enhance() do.
SimplifyAndEnhanceResult simplify_and_enhance(TriMesh& mesh, const SimplifyAndEnhanceParams& params = {});

/// The reductions' record (to_json of SimplifyResult) followed by "enhance": {stages, rounds,
/// flips, removed_vertices, split_edges}, as `meshprep simplify --enhance --json` writes it.
nlohmann::ordered_json to_json(const SimplifyAndEnhanceResult& result);

}  // namespace meshprep
