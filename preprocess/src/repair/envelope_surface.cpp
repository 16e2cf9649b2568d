#include "repair/envelope_surface.h"

#include "repair/winding_number.h"

#include "meshprep/quality/triangle_bvh.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace meshprep::detail {

namespace {

// The grid's shift off the bounding box, per axis, in cells: irrational (the golden ratio's and
// the square roots of 2 and 3's fractional parts), so that a plane a part's faces lie in, at a
// round coordinate, holds no grid point.
constexpr std::array<double, 3> kShift = {0.6180339887498949, 0.4142135623730950, 0.7320508075688772};
// A vertex stays this fraction of its edge away from the edge's ends (each face in its tetrahedron).
constexpr double kEndMargin = 1e-3;
// Bisection steps where a hole's span holds no face: the place to 2^-20 of the edge.
constexpr int kBisections = 20;

// Kuhn's split: the six tetrahedra of the unit cube along the diagonal (0,0,0)-(1,1,1), one per
// order of the axes; corner k of a tetrahedron is the sum of the first k unit steps.
constexpr std::array<std::array<int, 3>, 6> kAxisOrders = {
    {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};

struct Grid {
  Vec3 origin;
  double cell = 0;
  std::array<std::size_t, 3> points{};  // per axis
  std::size_t index(std::size_t i, std::size_t j, std::size_t k) const { return (k * points[1] + j) * points[0] + i; }
  Vec3 at(std::size_t i, std::size_t j, std::size_t k) const {
    return origin + cell * Vec3(static_cast<double>(i), static_cast<double>(j), static_cast<double>(k));
  }
  std::size_t size() const { return points[0] * points[1] * points[2]; }
};

Grid make_grid(const TriangleSoup& soup, std::size_t cells) {
  const Box3 box = bounding_box(soup);
  const Vec3 extent = box.max() - box.min();
  Grid grid;
  grid.cell = extent.maxCoeff() / static_cast<double>(cells);
  for (int a = 0; a < 3; ++a) {
    // A margin of more than one cell on each side: every grid point on the border is outside.
    grid.origin[a] = box.min()[a] - grid.cell * (1 + kShift[a]);
    grid.points[a] = static_cast<std::size_t>(std::ceil(extent[a] / grid.cell)) + 4;
  }
  return grid;
}

// Where on the segment from `inside` to `outside` the number drops under one half, as a fraction
// of the segment: at the face crossing past which it does, else (no face: a hole's span) by
// bisection.
double crossing_place(const Vec3& inside, const Vec3& outside, const TriangleSoup& soup, const TriangleBvh& faces,
                      const WindingNumber& winding) {
  Box3 span(inside.cwiseMin(outside), inside.cwiseMax(outside));
  std::vector<double> hits;
  faces.for_each_overlapping(span, [&](std::size_t f) {
    const Triangle& t = soup.triangles[f];
    // t in (0, 1]: the inside end is off every face (its number is defined there).
    const double at = ray_triangle(inside, outside - inside, soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]);
    if (at <= 1) hits.push_back(at);
  });
  std::sort(hits.begin(), hits.end());
  hits.erase(std::unique(hits.begin(), hits.end()), hits.end());
  const auto point = [&](double t) { return Vec3(inside + t * (outside - inside)); };
  if (hits.size() == 1) return hits.front();
  if (hits.size() > 1) {
    // The spans between the crossings: the first inside, the last outside; the first span found
    // outside ends at its crossing.
    for (std::size_t i = 0; i + 1 < hits.size(); ++i)
      if (winding.at(point(0.5 * (hits[i] + hits[i + 1]))) < 0.5) return hits[i];
    return hits.back();
  }
  double lo = 0, hi = 1;
  for (int step = 0; step < kBisections; ++step) {
    const double middle = 0.5 * (lo + hi);
    (winding.at(point(middle)) >= 0.5 ? lo : hi) = middle;
  }
  return 0.5 * (lo + hi);
}

// The steps of Kuhn's edges from a grid point (and their opposites): the neighbours whose labels
// one tetrahedron joins.
constexpr std::array<std::array<int, 3>, 7> kKuhnSteps = {
    {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}}};

// Groups of grid points of one label, joined through the tetrahedra's edges, smaller than a cube's
// eight points take the other label: a speck of the solid a single grid point caught in a wedge
// thinner than a cell (it would be a separate 24-face bubble), or a void as small. The group
// holding the grid's border, outside, always stays. Returns the points relabelled.
std::size_t relabel_specks(const Grid& grid, std::vector<std::uint8_t>& inside) {
  constexpr std::size_t kSpeck = 8;
  const std::array<std::size_t, 3> n = grid.points;
  std::vector<std::uint32_t> group(inside.size(), std::numeric_limits<std::uint32_t>::max());
  std::vector<std::size_t> members, stack;
  std::size_t relabelled = 0;
  std::uint32_t groups = 0;
  for (std::size_t start = 0; start < inside.size(); ++start) {
    if (group[start] != std::numeric_limits<std::uint32_t>::max()) continue;
    const std::uint8_t label = inside[start];
    members.clear();
    stack.assign(1, start);
    group[start] = groups;
    bool on_border = false;
    while (!stack.empty()) {
      const std::size_t p = stack.back();
      stack.pop_back();
      members.push_back(p);
      const std::size_t i = p % n[0], j = (p / n[0]) % n[1], k = p / (n[0] * n[1]);
      on_border = on_border || i == 0 || j == 0 || k == 0 || i + 1 == n[0] || j + 1 == n[1] || k + 1 == n[2];
      for (const auto& step : kKuhnSteps) {
        for (const int sign : {1, -1}) {
          const long long x = static_cast<long long>(i) + sign * step[0], y = static_cast<long long>(j) + sign * step[1],
                          z = static_cast<long long>(k) + sign * step[2];
          if (x < 0 || y < 0 || z < 0 || x >= static_cast<long long>(n[0]) || y >= static_cast<long long>(n[1]) ||
              z >= static_cast<long long>(n[2]))
            continue;
          const std::size_t q = grid.index(static_cast<std::size_t>(x), static_cast<std::size_t>(y),
                                           static_cast<std::size_t>(z));
          if (inside[q] != label || group[q] != std::numeric_limits<std::uint32_t>::max()) continue;
          group[q] = groups;
          stack.push_back(q);
        }
      }
    }
    ++groups;
    if (members.size() < kSpeck && !on_border) {
      for (const std::size_t p : members) inside[p] = !label;
      relabelled += members.size();
    }
  }
  return relabelled;
}

// Each face takes the patch of the soup's face nearest its centre.
void carry_patches(const TriangleSoup& soup, const TriangleBvh& faces, TriangleSoup& surface) {
  if (soup.patches.empty()) return;
  surface.patch_names = soup.patch_names;
  surface.patches.assign(surface.triangles.size(), 0);
  tbb::parallel_for(std::size_t{0}, surface.triangles.size(), [&](std::size_t f) {
    const Triangle& t = surface.triangles[f];
    const Vec3 centre = (surface.points[t[0]] + surface.points[t[1]] + surface.points[t[2]]) / 3;
    surface.patches[f] = soup.patches[faces.closest_point(centre).face];
  });
}

}  // namespace

EnvelopeSurface envelope_surface(const TriangleSoup& soup, std::size_t cells, const std::function<void()>& poll) {
  EnvelopeSurface result;
  const Grid grid = make_grid(soup, cells);
  result.cell = grid.cell;
  result.grid_points = grid.size();
  const WindingNumber winding(soup);
  const TriangleBvh faces(soup);

  // The label of every grid point: inside (the number at least one half) or not.
  std::vector<std::uint8_t> inside(grid.size(), 0);
  const std::array<std::size_t, 3> n = grid.points;
  // Layer by layer, the stop asked after each (the longest step on a fine grid).
  for (std::size_t k = 0; k < n[2]; ++k) {
    tbb::parallel_for(std::size_t{0}, n[1], [&](std::size_t j) {
      for (std::size_t i = 0; i < n[0]; ++i) inside[grid.index(i, j, k)] = winding.at(grid.at(i, j, k)) >= 0.5;
    });
    poll();
  }
  result.relabelled_specks = relabel_specks(grid, inside);

  // Marching tetrahedra: the vertices named by their grid edge (from point, one of 7 steps), each
  // face oriented from the inside corners to the outside ones (judged with the edges' middles,
  // before the vertices move along their edges).
  struct EdgeEnds {
    std::size_t in, out;
  };
  std::unordered_map<std::uint64_t, std::uint32_t> vertex_of_edge;
  std::vector<EdgeEnds> vertex_edges;
  std::vector<Vec3> middles;
  const auto grid_point = [&](std::size_t index) {
    const std::size_t i = index % n[0], j = (index / n[0]) % n[1], k = index / (n[0] * n[1]);
    return grid.at(i, j, k);
  };
  const auto vertex = [&](std::size_t a, std::size_t b, int step_code) {
    // a precedes b along the tetrahedron's path, so b - a is a step of 0s and 1s: the key.
    const std::uint64_t key = static_cast<std::uint64_t>(a) * 7 + static_cast<std::uint64_t>(step_code - 1);
    const auto [it, added] = vertex_of_edge.emplace(key, static_cast<std::uint32_t>(vertex_edges.size()));
    if (added) {
      vertex_edges.push_back(inside[a] ? EdgeEnds{a, b} : EdgeEnds{b, a});
      middles.push_back(0.5 * (grid_point(a) + grid_point(b)));
    }
    return it->second;
  };
  std::vector<Triangle>& triangles = result.surface.triangles;
  const auto add_face = [&](std::uint32_t x, std::uint32_t y, std::uint32_t z, const Vec3& outward) {
    const Vec3 normal = (middles[y] - middles[x]).cross(middles[z] - middles[x]);
    triangles.push_back(normal.dot(outward) >= 0 ? Triangle{x, y, z} : Triangle{x, z, y});
  };
  for (std::size_t k = 0; k + 1 < n[2]; ++k) {
    for (std::size_t j = 0; j + 1 < n[1]; ++j) {
      for (std::size_t i = 0; i + 1 < n[0]; ++i) {
        const std::size_t base = grid.index(i, j, k);
        const std::size_t cube[8] = {base,
                                     base + 1,
                                     base + n[0],
                                     base + n[0] + 1,
                                     base + n[0] * n[1],
                                     base + n[0] * n[1] + 1,
                                     base + n[0] * n[1] + n[0],
                                     base + n[0] * n[1] + n[0] + 1};
        int count = 0;
        for (const std::size_t c : cube) count += inside[c];
        if (count == 0 || count == 8) continue;
        for (const auto& order : kAxisOrders) {
          // Corner codes: bit a set = one step along axis a.
          std::array<int, 4> code{0, 0, 0, 7};
          code[1] = 1 << order[0];
          code[2] = code[1] | (1 << order[1]);
          std::array<std::size_t, 4> corner;
          for (int c = 0; c < 4; ++c) corner[c] = cube[code[c]];
          std::array<int, 4> in_list, out_list;
          int ins = 0, outs = 0;
          for (int c = 0; c < 4; ++c) (inside[corner[c]] ? in_list[ins++] : out_list[outs++]) = c;
          if (ins == 0 || outs == 0) continue;
          const auto on = [&](int c, int d) {
            const int lo = std::min(c, d), hi = std::max(c, d);
            return vertex(corner[lo], corner[hi], code[hi] - code[lo]);
          };
          Vec3 outward = Vec3::Zero();
          for (int c = 0; c < outs; ++c) outward += grid_point(corner[out_list[c]]) / outs;
          for (int c = 0; c < ins; ++c) outward -= grid_point(corner[in_list[c]]) / ins;
          if (ins == 1 || outs == 1) {
            const int apex = ins == 1 ? in_list[0] : out_list[0];
            const std::array<int, 3>& others =
                ins == 1 ? std::array<int, 3>{out_list[0], out_list[1], out_list[2]}
                         : std::array<int, 3>{in_list[0], in_list[1], in_list[2]};
            add_face(on(apex, others[0]), on(apex, others[1]), on(apex, others[2]), outward);
          } else {
            // Two inside (a, b), two outside (c, d): the quad ac, ad, bd, bc, split along ac-bd.
            const int a = in_list[0], b = in_list[1], c = out_list[0], d = out_list[1];
            const std::uint32_t ac = on(a, c), ad = on(a, d), bd = on(b, d), bc = on(b, c);
            add_face(ac, ad, bd, outward);
            add_face(ac, bd, bc, outward);
          }
        }
      }
    }
  }
  poll();

  // Each vertex moves from its edge's middle to where the soup is.
  std::vector<Vec3>& points = result.surface.points;
  points.resize(vertex_edges.size());
  tbb::parallel_for(std::size_t{0}, vertex_edges.size(), [&](std::size_t v) {
    const Vec3 from = grid_point(vertex_edges[v].in), to = grid_point(vertex_edges[v].out);
    const double t = std::clamp(crossing_place(from, to, soup, faces, winding), kEndMargin, 1 - kEndMargin);
    points[v] = from + t * (to - from);
  });
  poll();
  carry_patches(soup, faces, result.surface);
  return result;
}

}  // namespace meshprep::detail
