#pragma once
/// \file statistics.h
/// Summary statistics of a per-element measure.

#include <vector>

namespace meshprep {

/// min, mean, nearest-rank percentiles and max of a sample. Every field is NaN for an empty
/// sample. Percentile p is the value of rank ceil(p * n) in the sorted sample (nearest rank, the
/// definition the judge in shared/tools uses).
struct Distribution {
  double min, mean, p5, p50, p95, max;
  std::size_t count = 0;
};

/// Summarise `values` (taken by value: it is partially sorted). Non-finite values are ignored.
Distribution summarize(std::vector<double> values);

/// Nearest-rank percentile q in (0, 1] of a non-empty sample (reorders it).
double percentile(std::vector<double>& values, double q);

}  // namespace meshprep
