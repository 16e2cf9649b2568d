#include "smooth/noise_adaptive.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace meshprep::detail {
namespace {

// The high-pass of the narrow fit's moves measures the noise plus the roughness the fits cannot
// follow at the scale of an edge; on a coarse mesh that roughness is the mesh's own shape (the
// corpus's knot2, eight, hand: 2-3x the 0.1 % noise). Taking this share of it as the noise is the
// compromise measured on the 23 closed meshes of meshes/ and corpus/ at 0.1 % and 0.2 % noise
// (docs/smoothing.md): 0.45 keeps more coarse meshes below their noisy input and loses against
// Taubin on the dense ones, 0.8 the other way round.
constexpr double kNoiseShare = 0.6;
// The safety net, in noise levels: a vertex moves at most this far along its normal, and at most
// kTotalCap in all (the relaxation's tangential move included). The noise moved it by less than
// 2 levels with 95 % probability.
constexpr double kNormalCap = 2;
constexpr double kTotalCap = 3;
// Median of |N(0, 1)|.
constexpr double kHalfNormalMedian = 0.6745;

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// The share of a move's variance that is noise: 1 - 2 a_own + sum a_j^2 (FitWeights).
double noise_factor(const FitWeights& w) { return std::max(1e-3, 1 - 2 * w.own + w.sum_of_squares); }

// Mean of f(j) over i and its 1-ring, over the j where `has(j)`; NaN if none.
template <class Has, class F>
double ring_mean(const VertexGraph& graph, std::size_t i, Has has, F f) {
  double sum = 0;
  int count = 0;
  auto add = [&](std::size_t j) {
    if (!has(j)) return;
    sum += f(j);
    ++count;
  };
  add(i);
  for (std::uint32_t e = graph.first[i]; e < graph.first[i + 1]; ++e) add(graph.neighbour[e]);
  return count > 0 ? sum / count : std::nan("");
}

}  // namespace

NoiseAdaptiveCounts choose_moves(const std::vector<Vec3>& points, const VertexGraph& graph,
                                 const std::array<MoveProposal, 2>& proposals, std::vector<Vec3>& moved) {
  const std::size_t n = points.size();
  NoiseAdaptiveCounts counts;
  auto ring_size = [&](std::size_t i) { return static_cast<double>(graph.first[i + 1] - graph.first[i]); };

  // 1. The noise: white noise moves each vertex on its own, a fit's error is smooth along the
  // surface. So the narrow fit's move less the mean of its 1-ring's keeps the noise (variance
  // s^2 noise_factor (1 + 1/k)) and little of the error; its median absolute value gives s.
  const MoveProposal& narrow = proposals[1];
  std::vector<double> high(n, std::nan(""));
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    if (!narrow.has(i)) return;
    double sum = 0;
    int k = 0;
    for (std::uint32_t e = graph.first[i]; e < graph.first[i + 1]; ++e)
      if (narrow.has(graph.neighbour[e])) {
        sum += narrow.along_normal[graph.neighbour[e]];
        ++k;
      }
    if (k < 2) return;
    high[i] = std::abs(narrow.along_normal[i] - sum / k) / std::sqrt(noise_factor(narrow.weights[i]) * (1 + 1.0 / k));
  });
  std::vector<double> highs;
  for (const double h : high)
    if (!std::isnan(h)) highs.push_back(h);
  counts.noise = kNoiseShare * median(highs) / kHalfNormalMedian;
  const double noise2 = counts.noise * counts.noise;

  // 2. Each proposal's squared bias at each vertex. Its smooth part: the mean move over the vertex
  // and its 1-ring, squared, less that mean's noise variance, averaged over the 1-ring again (one
  // difference alone is too noisy to clamp at 0 without a bias of its own). Its rough part: where
  // the two fits disagree by more than their noise explains, at least one is wrong; the excess
  // (over the 1-ring) is added to both.
  std::array<std::vector<double>, 2> bias2;
  for (std::size_t c = 0; c < 2; ++c) {
    const MoveProposal& proposal = proposals[c];
    auto has = [&](std::size_t j) { return proposal.has(j); };
    std::vector<double> smooth(n, std::nan(""));
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
      if (!has(i)) return;
      const double mean = ring_mean(graph, i, has, [&](std::size_t j) { return proposal.along_normal[j]; });
      smooth[i] = mean * mean - noise2 * noise_factor(proposal.weights[i]) / (ring_size(i) + 1);
    });
    bias2[c].assign(n, std::nan(""));
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
      if (has(i)) bias2[c][i] = std::max(0.0, ring_mean(graph, i, [&](std::size_t j) { return !std::isnan(smooth[j]); },
                                                         [&](std::size_t j) { return smooth[j]; }));
    });
  }
  auto both = [&](std::size_t j) { return proposals[0].has(j) && proposals[1].has(j); };
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    if (!both(i)) return;
    const double disagreement = std::max(0.0, ring_mean(graph, i, both, [&](std::size_t j) {
      const double expected = noise2 * std::abs(proposals[1].weights[j].sum_of_squares - proposals[0].weights[j].sum_of_squares);
      return std::pow(proposals[0].along_normal[j] - proposals[1].along_normal[j], 2) - expected;
    }));
    for (auto& b : bias2) b[i] += disagreement;
  });

  // 3. Per vertex: each proposal shrunk towards the input point by the alpha that minimises its
  // expected squared error (s^2 (1 - a_own) / (s^2 noise_factor + b^2)), capped by the safety net;
  // the proposal with the least error wins, unless staying (error s^2) is better.
  std::vector<char> stays(n, 0);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    double best_risk = noise2, best_alpha = 0;
    int best = -1;
    for (int c = 0; c < 2; ++c) {
      const MoveProposal& proposal = proposals[static_cast<std::size_t>(c)];
      if (!proposal.has(i)) continue;
      const double taken = noise2 * (1 - proposal.weights[i].own);  // -E[eps d]: the noise the move takes away
      const double spread = noise2 * noise_factor(proposal.weights[i]) + bias2[static_cast<std::size_t>(c)][i];  // E[d^2]
      double alpha = spread > 0 ? std::clamp(taken / spread, 0.0, 1.0) : 0.0;
      const double along = std::abs(proposal.along_normal[i]), total = (proposal.target[i] - points[i]).norm();
      if (along > 0) alpha = std::min(alpha, kNormalCap * counts.noise / along);
      if (total > 0) alpha = std::min(alpha, kTotalCap * counts.noise / total);
      const double risk = noise2 - 2 * alpha * taken + alpha * alpha * spread;
      if (risk < best_risk) {
        best_risk = risk;
        best_alpha = alpha;
        best = c;
      }
    }
    if (best >= 0)
      moved[i] = points[i] + best_alpha * (proposals[static_cast<std::size_t>(best)].target[i] - points[i]);
    else if (proposals[0].has(i) || proposals[1].has(i)) {
      moved[i] = points[i];
      stays[i] = 1;
    }
  });
  counts.not_moved = static_cast<std::size_t>(std::count(stays.begin(), stays.end(), 1));
  return counts;
}

}  // namespace meshprep::detail
