#pragma once
/// \file size_conformity.h
/// How well tets follow a size field (core/size_field.h): each edge's length over the field's h
/// at its midpoint, and the size jump between neighbouring tets against the jump the field allows.

#include "meshprep/core/size_field.h"
#include "meshprep/fem/tet_mesh.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <vector>

namespace meshprep {

/// The band an edge's length / h should lie in (issue 49's acceptance: 90 % of the edges).
inline constexpr double kSizeBandLow = 0.7, kSizeBandHigh = 1.4;

struct SizeConformity {
  std::size_t edges = 0;
  /// length / h over the edges: percentiles and the share within [kSizeBandLow, kSizeBandHigh].
  double ratio_p01 = 0, ratio_p05 = 0, ratio_median = 0, ratio_p95 = 0, ratio_p99 = 0;
  double within_band = 0;
  /// Over each pair of tets sharing a face: the ratio of their mean edge lengths (>= 1) over the
  /// ratio of the field at their centroids (>= 1): how much more than the field allows their sizes
  /// jump. Its 99th percentile and largest value.
  double grading_excess_p99 = 0, grading_excess_max = 0;
  /// Every edge's length / h, sorted (for the report's histogram; not in the JSON).
  std::vector<double> edge_ratios;
};

SizeConformity measure_size_conformity(const TetMesh& tets, const SizeField& field);

/// {edges, ratio: {p01, p05, median, p95, p99}, within_band: {low, high, share}, grading_excess: {p99, max}}.
nlohmann::ordered_json to_json(const SizeConformity& conformity);

}  // namespace meshprep
