#include "meshprep/fem/size_conformity.h"

#include "tet_faces.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace meshprep {
namespace {

// The value at fraction q of the sorted values (nearest rank).
double percentile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0;
  const auto i = static_cast<std::size_t>(std::lround(q * static_cast<double>(sorted.size() - 1)));
  return sorted[i];
}

}  // namespace

SizeConformity measure_size_conformity(const TetMesh& mesh, const SizeField& field) {
  SizeConformity c;
  const std::vector<Vec3>& p = mesh.points;
  // Each edge once: the pairs of corners, sorted and deduplicated.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(6 * mesh.tets.size());
  std::vector<double> mean_edge(mesh.tets.size()), tet_h(mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const Tetrahedron& tet = mesh.tets[t];
    double sum = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        edges.emplace_back(std::min(tet[i], tet[j]), std::max(tet[i], tet[j]));
        sum += (p[tet[i]] - p[tet[j]]).norm();
      }
    mean_edge[t] = sum / 6;
    tet_h[t] = field((p[tet[0]] + p[tet[1]] + p[tet[2]] + p[tet[3]]) / 4);
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<double> ratios;
  ratios.reserve(edges.size());
  std::size_t within = 0;
  for (const auto& [a, b] : edges) {
    const double h = field((p[a] + p[b]) / 2);
    const double ratio = (p[a] - p[b]).norm() / h;
    ratios.push_back(ratio);
    if (ratio >= kSizeBandLow && ratio <= kSizeBandHigh) ++within;
  }
  std::sort(ratios.begin(), ratios.end());
  c.edges = ratios.size();
  c.within_band = ratios.empty() ? 0 : static_cast<double>(within) / static_cast<double>(ratios.size());
  c.ratio_p01 = percentile(ratios, 0.01);
  c.ratio_p05 = percentile(ratios, 0.05);
  c.ratio_median = percentile(ratios, 0.5);
  c.ratio_p95 = percentile(ratios, 0.95);
  c.ratio_p99 = percentile(ratios, 0.99);
  c.edge_ratios = std::move(ratios);
  std::vector<double> excess;
  const detail::TetFaces faces(mesh.tets);
  const auto& entries = faces.entries();
  for (std::size_t first = 0; first < entries.size();) {
    const std::size_t n = faces.group_size(first);
    if (n == 2) {
      const std::uint32_t s = entries[first].tet_face / 4, t = entries[first + 1].tet_face / 4;
      const double size_jump = std::max(mean_edge[s], mean_edge[t]) / std::min(mean_edge[s], mean_edge[t]);
      const double allowed = std::max(tet_h[s], tet_h[t]) / std::min(tet_h[s], tet_h[t]);
      if (std::isfinite(size_jump)) excess.push_back(size_jump / allowed);
    }
    first += n;
  }
  std::sort(excess.begin(), excess.end());
  c.grading_excess_p99 = percentile(excess, 0.99);
  c.grading_excess_max = excess.empty() ? 0 : excess.back();
  return c;
}

nlohmann::ordered_json to_json(const SizeConformity& c) {
  return {{"edges", c.edges},
          {"ratio", {{"p01", c.ratio_p01}, {"p05", c.ratio_p05}, {"median", c.ratio_median}, {"p95", c.ratio_p95}, {"p99", c.ratio_p99}}},
          {"within_band", {{"low", kSizeBandLow}, {"high", kSizeBandHigh}, {"share", c.within_band}}},
          {"grading_excess", {{"p99", c.grading_excess_p99}, {"max", c.grading_excess_max}}}};
}

}  // namespace meshprep
