#include "meshprep/quality/statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace meshprep {

double percentile(std::vector<double>& values, double q) {
  const auto n = values.size();
  auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(n)));
  rank = std::clamp<std::size_t>(rank, 1, n);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank - 1), values.end());
  return values[rank - 1];
}

Distribution summarize(std::vector<double> values) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
               values.end());
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  Distribution d{nan, nan, nan, nan, nan, nan, values.size()};
  if (values.empty()) return d;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  d.min = *lo;
  d.max = *hi;
  d.mean = std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
  d.p5 = percentile(values, 0.05);
  d.p50 = percentile(values, 0.50);
  d.p95 = percentile(values, 0.95);
  return d;
}

}  // namespace meshprep
