#pragma once
// How far each vertex of RBF smoothing moves, from the noise the mesh shows (smooth.h,
// docs/smoothing.md "Adapting to the mesh"): the fits propose targets, this decides per vertex how
// much of which proposal to take, or none.

#include "smooth/smoothing_neighbourhoods.h"

#include "meshprep/core/mesh.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace meshprep::detail {

/// The fitted height at a vertex is linear in its sites' heights, sum_j a_j z_j: a_own is the
/// vertex's own coefficient, sum_of_squares sum_j a_j^2. Under white noise of variance s^2 the move
/// d = fit - height has E[-eps d] = s^2 (1 - a_own) and variance s^2 (1 - 2 a_own + sum_of_squares).
struct FitWeights {
  double own = 0;
  double sum_of_squares = 1;
};

/// One family of local fits: per vertex, where the fit puts it (`target`, relaxation included), the
/// signed move of the vertex itself onto its local surface along its normal (NaN: no proposal) and
/// the fit's weights.
struct MoveProposal {
  explicit MoveProposal(std::size_t n) : target(n), along_normal(n, kNone), weights(n) {}
  void set(std::size_t i, const Vec3& to, double normal_move, const FitWeights& fit) {
    target[i] = to;
    along_normal[i] = normal_move;
    weights[i] = fit;
  }
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  bool has(std::size_t i) const { return !std::isnan(along_normal[i]); }

  std::vector<Vec3> target;
  std::vector<double> along_normal;
  std::vector<FitWeights> weights;
};

/// What the choice found.
struct NoiseAdaptiveCounts {
  double noise = 0;               ///< the noise level used (mesh units)
  std::size_t not_moved = 0;      ///< vertices with a proposal for which none beat staying
};

/// Per vertex with a proposal, the point `points[i] + alpha (target - points[i])` of the proposal
/// whose estimated squared error is least, or points[i] when staying is better; written to `moved`
/// (other vertices are left as they are). proposals[0] is the wide fit, proposals[1] the narrow one
/// (the noise is measured on it).
NoiseAdaptiveCounts choose_moves(const std::vector<Vec3>& points, const VertexGraph& graph,
                                 const std::array<MoveProposal, 2>& proposals, std::vector<Vec3>& moved);

}  // namespace meshprep::detail
