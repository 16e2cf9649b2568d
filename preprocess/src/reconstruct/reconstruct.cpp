#include "meshprep/preprocess/reconstruct/reconstruct.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/finite_points.h"

#include "reconstruct/grid_gaps.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <initializer_list>
#include <numeric>

namespace meshprep {
namespace {

using Eigen::Vector2d;

// The grid's size: explicit columns and rows, a spacing, or about `vertices` vertices on square
// cells over the footprint.
PlaneGrid grid_over(const Eigen::AlignedBox2d& box, const ReconstructParams& params) {
  std::size_t nx = params.columns, ny = params.rows;
  const Vector2d size = box.sizes();
  double spacing = params.spacing;
  if (params.vertices > 0) {
    if (!(size.minCoeff() > 0)) throw InvalidInput("the points lie on a line: no footprint to mesh");
    spacing = std::sqrt(size.x() * size.y() / static_cast<double>(params.vertices));
  }
  if (spacing > 0) {
    const Vector2d cells = size / spacing;
    if (!(cells.maxCoeff() < 1e8)) throw InvalidInput("the spacing gives a grid of more than 10^8 vertices");
    // A requested spacing is an upper bound (round up); a vertex count a target (round).
    auto count = [&](double c) { return static_cast<std::size_t>(params.vertices > 0 ? std::round(c) : std::ceil(c)) + 1; };
    nx = count(cells.x());
    ny = count(cells.y());
  }
  if (nx < 2 || ny < 2 || static_cast<double>(nx) * static_cast<double>(ny) > 1e8)
    throw InvalidInput("the grid needs between 2 x 2 and 10^8 vertices");
  PlaneGrid grid;
  grid.origin = box.min();
  grid.columns = nx;
  grid.rows = ny;
  grid.step = Vector2d(size.x() / static_cast<double>(nx - 1), size.y() / static_cast<double>(ny - 1));
  return grid;
}

// Two triangles per grid cell (i, j): k = 0 below the diagonal (i, j)-(i+1, j+1), k = 1 above.
// Triangle index 2 (j (columns - 1) + i) + k; its centre is at (i + 2/3, j + 1/3) or
// (i + 1/3, j + 2/3) grid steps from the origin.
struct GridTriangles {
  const PlaneGrid& grid;
  std::size_t cells_x() const { return grid.columns - 1; }
  std::size_t count() const { return 2 * cells_x() * (grid.rows - 1); }
  std::vector<Triangle> all() const {
    std::vector<Triangle> triangles;
    triangles.reserve(count());
    for (std::size_t j = 0; j + 1 < grid.rows; ++j)
      for (std::size_t i = 0; i < cells_x(); ++i) {
        const auto v = static_cast<std::uint32_t>(j * grid.columns + i), up = v + static_cast<std::uint32_t>(grid.columns);
        triangles.push_back({v, v + 1, up + 1});
        triangles.push_back({v, up + 1, up});
      }
    return triangles;
  }
  // The (up to six) triangles at vertex v: both of cell (i-1, j-1), k = 1 of (i, j-1), k = 0 of
  // (i-1, j), both of (i, j), where they exist.
  void around(std::uint32_t v, std::vector<std::uint32_t>& triangles) const {
    triangles.clear();
    const std::size_t i = v % grid.columns, j = v / grid.columns;
    auto add = [&](std::size_t ci, std::size_t cj, std::initializer_list<std::size_t> ks) {
      for (const std::size_t k : ks) triangles.push_back(static_cast<std::uint32_t>(2 * (cj * cells_x() + ci) + k));
    };
    if (j > 0) {
      if (i > 0) add(i - 1, j - 1, {0, 1});
      if (i < cells_x()) add(i, j - 1, {1});
    }
    if (j + 1 < grid.rows) {
      if (i > 0) add(i - 1, j, {0});
      if (i < cells_x()) add(i, j, {0, 1});
    }
  }
};

// Marks the triangles whose centre lies within max_gap of a sample (in the plane): each sample
// covers, row by row, an interval of centres. O(samples x rows of the disc), no per-triangle
// search. In parallel over bands of rows, each with the samples (sorted by row) that can reach it.
std::vector<char> near_samples(const std::vector<Vector2d>& samples, const PlaneGrid& grid, double max_gap) {
  const GridTriangles triangles{grid};
  std::vector<char> covered(triangles.count(), 0);
  const double offsets[2][2] = {{2.0 / 3, 1.0 / 3}, {1.0 / 3, 2.0 / 3}};  // centre of triangle k in its cell
  const auto rows = static_cast<long long>(grid.rows) - 1, columns = static_cast<long long>(grid.columns) - 1;
  const Vector2d reach = Vector2d::Constant(max_gap).cwiseQuotient(grid.step);
  std::vector<Vector2d> q(samples.size());  // in grid steps from the origin, by row
  for (std::size_t s = 0; s < samples.size(); ++s) q[s] = (samples[s] - grid.origin).cwiseQuotient(grid.step);
  std::sort(q.begin(), q.end(), [](const Vector2d& a, const Vector2d& b) { return a.y() < b.y(); });
  constexpr long long kBand = 32;  // rows per task
  tbb::parallel_for(0LL, (rows + kBand - 1) / kBand, [&](long long band) {
    const long long first = band * kBand, last = std::min(rows, first + kBand) - 1;
    auto s = std::lower_bound(q.begin(), q.end(), static_cast<double>(first) - reach.y() - 1,
                              [](const Vector2d& a, double y) { return a.y() < y; });
    for (; s != q.end() && s->y() <= static_cast<double>(last) + reach.y() + 1; ++s)
      for (int k = 0; k < 2; ++k) {
        const long long j0 = std::max(first, static_cast<long long>(std::ceil(s->y() - reach.y() - offsets[k][1])));
        const long long j1 = std::min(last, static_cast<long long>(std::floor(s->y() + reach.y() - offsets[k][1])));
        for (long long j = j0; j <= j1; ++j) {
          const double dy = (static_cast<double>(j) + offsets[k][1] - s->y()) * grid.step.y();
          const double half = std::sqrt(std::max(0.0, max_gap * max_gap - dy * dy)) / grid.step.x();
          const long long i0 = std::max(0LL, static_cast<long long>(std::ceil(s->x() - half - offsets[k][0])));
          const long long i1 = std::min(columns - 1, static_cast<long long>(std::floor(s->x() + half - offsets[k][0])));
          for (long long i = i0; i <= i1; ++i) covered[2 * static_cast<std::size_t>(j * columns + i) + static_cast<std::size_t>(k)] = 1;
        }
      }
  });
  return covered;
}

// Leaving triangles out over gaps can leave two fans of triangles touching at one vertex (a
// bow tie: not a manifold). At every such vertex the largest fan stays and the others go, until
// none is left; only the corners of left-out triangles can be such vertices. Returns the number
// of triangles dropped.
std::size_t drop_bowties(const GridTriangles& grid, const std::vector<Triangle>& triangles, std::vector<char>& kept) {
  std::vector<std::uint32_t> suspects;
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (!kept[t]) suspects.insert(suspects.end(), triangles[t].begin(), triangles[t].end());
  std::size_t dropped = 0;
  std::vector<std::uint32_t> fan;
  while (!suspects.empty()) {
    std::sort(suspects.begin(), suspects.end());
    suspects.erase(std::unique(suspects.begin(), suspects.end()), suspects.end());
    std::vector<std::uint32_t> next;
    for (const std::uint32_t v : suspects) {
      grid.around(v, fan);
      fan.erase(std::remove_if(fan.begin(), fan.end(), [&](std::uint32_t t) { return !kept[t]; }), fan.end());
      if (fan.size() < 2) continue;
      // Group the triangles at v: two are in one fan if they share an edge at v.
      std::vector<std::size_t> group(fan.size());
      std::iota(group.begin(), group.end(), 0);
      auto root = [&](std::size_t a) {
        while (group[a] != a) a = group[a] = group[group[a]];
        return a;
      };
      for (std::size_t a = 0; a < fan.size(); ++a)
        for (std::size_t b = a + 1; b < fan.size(); ++b) {
          int shared = 0;
          for (const std::uint32_t x : triangles[fan[a]])
            for (const std::uint32_t y : triangles[fan[b]]) shared += x == y;
          if (shared == 2) group[root(a)] = root(b);
        }
      std::vector<std::size_t> size(fan.size(), 0);
      for (std::size_t a = 0; a < fan.size(); ++a) ++size[root(a)];
      const auto largest = static_cast<std::size_t>(std::max_element(size.begin(), size.end()) - size.begin());
      if (size[largest] == fan.size()) continue;
      for (std::size_t a = 0; a < fan.size(); ++a)
        if (root(a) != largest) {
          kept[fan[a]] = 0;
          ++dropped;
          next.insert(next.end(), triangles[fan[a]].begin(), triangles[fan[a]].end());
        }
    }
    suspects.swap(next);
  }
  return dropped;
}

}  // namespace

PartitionOfUnity fit_surface(const std::vector<Vec3>& points, const ReconstructParams& params) {
  if (!(params.spacing >= 0 && std::isfinite(params.spacing)) || !(params.max_gap >= 0 && std::isfinite(params.max_gap)))
    throw InvalidInput("the grid spacing and the largest gap must be finite numbers >= 0 (0: automatic)");
  return PartitionOfUnity(points, params.fit);
}

ReconstructResult mesh_surface(const PartitionOfUnity& pu, const ReconstructParams& params, std::size_t refinement) {
  if (refinement < 1) throw InvalidInput("the grid refinement must be at least 1");
  ReconstructResult result;
  result.patches = pu.patches();
  result.variation_threshold = pu.variation_threshold();
  result.grown_patches = pu.grown_patches();
  result.patch_variation = pu.patch_variation();
  result.normal = pu.frame().normal();
  result.max_gap = params.max_gap > 0 ? params.max_gap : 3.0 * pu.median_sample_spacing();

  PlaneGrid grid = grid_over(pu.footprint(), params);
  result.columns = grid.columns;
  result.rows = grid.rows;
  if (refinement > 1) {
    grid.columns = refinement * (grid.columns - 1) + 1;
    grid.rows = refinement * (grid.rows - 1) + 1;
    grid.step /= static_cast<double>(refinement);
  }
  const std::vector<PartitionOfUnity::Value> heights = pu.evaluate_grid(grid);

  const GridTriangles cells{grid};
  const std::vector<Triangle> triangles = cells.all();
  std::vector<char> kept = near_samples(pu.sample_positions(), grid, result.max_gap), filled;
  if (params.fill_holes) {
    detail::fill_interior_gaps(grid, kept, filled);
    detail::keep_largest_piece(grid, kept);
  }
  result.gap_triangles = static_cast<std::size_t>(std::count(kept.begin(), kept.end(), 0));
  result.gap_triangles += drop_bowties(cells, triangles, kept);
  if (params.fill_holes) result.gap_triangles += detail::keep_largest_piece(grid, kept);

  // Keep the vertices some triangle uses, in grid order.
  constexpr std::uint32_t unused = ~std::uint32_t(0);
  std::vector<std::uint32_t> renumber(heights.size(), unused);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (kept[t])
      for (const std::uint32_t v : triangles[t]) renumber[v] = 0;
  const auto used = static_cast<std::size_t>(std::count(renumber.begin(), renumber.end(), 0u));
  result.mesh.points.reserve(used);
  result.vertex_variation.reserve(used);
  for (std::size_t j = 0; j < grid.rows; ++j)
    for (std::size_t i = 0; i < grid.columns; ++i) {
      const std::size_t v = j * grid.columns + i;
      if (renumber[v] == unused) continue;
      renumber[v] = static_cast<std::uint32_t>(result.mesh.points.size());
      const Vector2d q = grid.at(i, j);
      result.mesh.points.push_back(pu.frame().to_world(Vec3(q.x(), q.y(), heights[v].height)));
      result.vertex_variation.push_back(heights[v].variation);
    }
  result.mesh.triangles.reserve(triangles.size() - result.gap_triangles);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (!kept[t]) continue;
    if (!filled.empty() && filled[t]) result.filled_faces.push_back(result.mesh.triangles.size());
    Triangle corners = triangles[t];
    for (std::uint32_t& v : corners) v = renumber[v];
    result.mesh.triangles.push_back(corners);
  }
  result.filled_triangles = result.filled_faces.size();
  require_finite_points(result.mesh.points, "reconstruct");
  return result;
}

ReconstructResult reconstruct_surface(const std::vector<Vec3>& points, const ReconstructParams& params) {
  const auto start = std::chrono::steady_clock::now();
  ReconstructResult result = mesh_surface(fit_surface(points, params), params);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace meshprep
