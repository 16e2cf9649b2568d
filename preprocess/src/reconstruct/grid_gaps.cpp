#include "reconstruct/grid_gaps.h"

#include <algorithm>
#include <array>

namespace meshprep::detail {
namespace {

constexpr std::size_t kNone = ~std::size_t(0);

// The three triangles sharing an edge with triangle t (kNone across the grid's border).
std::array<std::size_t, 3> edge_neighbours(const PlaneGrid& grid, std::size_t t) {
  const std::size_t cells_x = grid.columns - 1, cells_y = grid.rows - 1;
  const std::size_t cell = t / 2, i = cell % cells_x, j = cell / cells_x;
  auto at = [&](std::size_t ci, std::size_t cj, std::size_t k) { return 2 * (cj * cells_x + ci) + k; };
  if (t % 2 == 0)  // corners (i, j), (i+1, j), (i+1, j+1): bottom, right, diagonal
    return {j > 0 ? at(i, j - 1, 1) : kNone, i + 1 < cells_x ? at(i + 1, j, 1) : kNone, t + 1};
  // corners (i, j), (i+1, j+1), (i, j+1): top, left, diagonal
  return {j + 1 < cells_y ? at(i, j + 1, 0) : kNone, i > 0 ? at(i - 1, j, 0) : kNone, t - 1};
}

bool on_border(const PlaneGrid& grid, std::size_t t) {
  const std::array<std::size_t, 3> n = edge_neighbours(grid, t);
  return std::find(n.begin(), n.end(), kNone) != n.end();
}

// Labels the edge-connected pieces of the triangles with `member[t] == value`; returns the label
// of each triangle (kNone for non-members) and fills `sizes`.
std::vector<std::size_t> pieces(const PlaneGrid& grid, const std::vector<char>& member, char value,
                                std::vector<std::size_t>& sizes) {
  std::vector<std::size_t> label(member.size(), kNone), stack;
  for (std::size_t seed = 0; seed < member.size(); ++seed) {
    if (member[seed] != value || label[seed] != kNone) continue;
    const std::size_t id = sizes.size();
    sizes.push_back(0);
    label[seed] = id;
    stack.push_back(seed);
    while (!stack.empty()) {
      const std::size_t t = stack.back();
      stack.pop_back();
      ++sizes[id];
      for (const std::size_t n : edge_neighbours(grid, t))
        if (n != kNone && member[n] == value && label[n] == kNone) {
          label[n] = id;
          stack.push_back(n);
        }
    }
  }
  return label;
}

}  // namespace

void fill_interior_gaps(const PlaneGrid& grid, std::vector<char>& kept, std::vector<char>& filled) {
  std::vector<std::size_t> sizes;
  const std::vector<std::size_t> label = pieces(grid, kept, 0, sizes);
  std::vector<char> outside(sizes.size(), 0);  // a gap piece reaching the border lies outside the footprint
  for (std::size_t t = 0; t < kept.size(); ++t)
    if (label[t] != kNone && on_border(grid, t)) outside[label[t]] = 1;
  filled.assign(kept.size(), 0);
  for (std::size_t t = 0; t < kept.size(); ++t)
    if (label[t] != kNone && !outside[label[t]]) kept[t] = filled[t] = 1;
}

std::size_t keep_largest_piece(const PlaneGrid& grid, std::vector<char>& kept) {
  std::vector<std::size_t> sizes;
  const std::vector<std::size_t> label = pieces(grid, kept, 1, sizes);
  if (sizes.size() < 2) return 0;
  const auto largest = static_cast<std::size_t>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  std::size_t count = 0;
  for (std::size_t t = 0; t < kept.size(); ++t)
    if (label[t] != kNone && label[t] != largest) {
      kept[t] = 0;
      ++count;
    }
  return count;
}

}  // namespace meshprep::detail
