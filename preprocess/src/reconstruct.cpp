#include "meshprep/preprocess/reconstruct.h"

#include "meshprep/core/errors.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace meshprep {
namespace {

using Eigen::Vector2d;

// Leaving triangles out over gaps can leave two fans of triangles touching at one vertex (a
// bow tie: not a manifold). At every such vertex the largest fan stays and the others go, until
// none is left. Returns the number of triangles dropped.
std::size_t drop_bowties(std::vector<Triangle>& triangles, std::size_t vertex_count) {
  std::size_t dropped = 0;
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<std::vector<std::uint32_t>> around(vertex_count);
    for (std::size_t t = 0; t < triangles.size(); ++t)
      for (const std::uint32_t v : triangles[t]) around[v].push_back(static_cast<std::uint32_t>(t));
    std::vector<char> drop(triangles.size(), 0);
    for (std::uint32_t v = 0; v < vertex_count; ++v) {
      const std::vector<std::uint32_t>& fan = around[v];
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
      const std::size_t largest = static_cast<std::size_t>(std::max_element(size.begin(), size.end()) - size.begin());
      if (size[largest] == fan.size()) continue;
      for (std::size_t a = 0; a < fan.size(); ++a)
        if (root(a) != largest && !drop[fan[a]]) {
          drop[fan[a]] = 1;
          ++dropped;
          changed = true;
        }
    }
    std::vector<Triangle> kept;
    for (std::size_t t = 0; t < triangles.size(); ++t)
      if (!drop[t]) kept.push_back(triangles[t]);
    triangles.swap(kept);
  }
  return dropped;
}

}  // namespace

ReconstructResult reconstruct_surface(const std::vector<Vec3>& points, const ReconstructParams& params) {
  const PartitionOfUnity pu(points, params.fit);
  ReconstructResult result;
  result.patches = pu.patches();
  result.normal = pu.frame().normal();
  result.max_gap = params.max_gap > 0 ? params.max_gap : 3.0 * pu.median_sample_spacing();

  const Eigen::AlignedBox2d box = pu.footprint();
  std::size_t nx = params.columns, ny = params.rows;
  if (params.spacing > 0) {
    const Vector2d cells = box.sizes() / params.spacing;
    if (!(cells.maxCoeff() < 1e8)) throw InvalidInput("the spacing gives a grid of more than 10^8 vertices");
    nx = static_cast<std::size_t>(std::ceil(cells.x())) + 1;
    ny = static_cast<std::size_t>(std::ceil(cells.y())) + 1;
  }
  if (nx < 2 || ny < 2 || static_cast<double>(nx) * static_cast<double>(ny) > 1e8)
    throw InvalidInput("the grid needs between 2 x 2 and 10^8 vertices");
  const Vector2d step(box.sizes().x() / static_cast<double>(nx - 1), box.sizes().y() / static_cast<double>(ny - 1));
  std::vector<Vec3> vertices(nx * ny);
  // Every vertex is independent: evaluated in parallel, each written to its own slot (deterministic).
  tbb::parallel_for(std::size_t(0), ny, [&](std::size_t j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const Vector2d q = box.min() + Vector2d(static_cast<double>(i) * step.x(), static_cast<double>(j) * step.y());
      vertices[j * nx + i] = pu.surface_point(q.x(), q.y());
    }
  });

  std::vector<char> used(vertices.size(), 0);
  std::vector<Triangle> triangles;
  auto id = [nx](std::size_t i, std::size_t j) { return static_cast<std::uint32_t>(j * nx + i); };
  for (std::size_t j = 0; j + 1 < ny; ++j)
    for (std::size_t i = 0; i + 1 < nx; ++i) {
      const Vector2d corner = box.min() + Vector2d(static_cast<double>(i) * step.x(), static_cast<double>(j) * step.y());
      const Vector2d centres[2] = {corner + Vector2d(2 * step.x(), step.y()) / 3.0,
                                   corner + Vector2d(step.x(), 2 * step.y()) / 3.0};
      const Triangle cell[2] = {{id(i, j), id(i + 1, j), id(i + 1, j + 1)}, {id(i, j), id(i + 1, j + 1), id(i, j + 1)}};
      for (int k = 0; k < 2; ++k) {
        if (pu.nearest_sample_distance(centres[k].x(), centres[k].y()) > result.max_gap) {
          ++result.gap_triangles;
          continue;
        }
        triangles.push_back(cell[k]);
        for (const std::uint32_t v : cell[k]) used[v] = 1;
      }
    }
  result.gap_triangles += drop_bowties(triangles, vertices.size());
  std::fill(used.begin(), used.end(), 0);
  for (const Triangle& t : triangles)
    for (const std::uint32_t v : t) used[v] = 1;
  // Keep the vertices some triangle uses, in order.
  std::vector<std::uint32_t> renumber(vertices.size(), 0);
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (!used[v]) continue;
    renumber[v] = static_cast<std::uint32_t>(result.mesh.points.size());
    result.mesh.points.push_back(vertices[v]);
  }
  for (Triangle t : triangles) {
    for (std::uint32_t& v : t) v = renumber[v];
    result.mesh.triangles.push_back(t);
  }
  return result;
}

}  // namespace meshprep
