#pragma once
// Gaps in a reconstruction grid (reconstruct.cpp): which left-out triangles are holes in the data
// and which lie outside the footprint, and the connected pieces of what is kept. Triangles are
// numbered as in reconstruct.cpp: 2 (j (columns - 1) + i) + k for cell (i, j), k = 0 below the
// diagonal (i, j)-(i+1, j+1), k = 1 above it.

#include "meshprep/preprocess/reconstruct/partition_of_unity.h"

#include <vector>

namespace meshprep::detail {

/// Left-out triangles (`kept` 0) that cannot be reached from the grid's border through other
/// left-out triangles are holes in the data: they are kept (set to 1) and marked in `filled`
/// (resized to kept.size()).
void fill_interior_gaps(const PlaneGrid& grid, std::vector<char>& kept, std::vector<char>& filled);

/// Leaves out every kept triangle that is not edge-connected to the largest kept piece.
/// Returns how many were left out.
std::size_t keep_largest_piece(const PlaneGrid& grid, std::vector<char>& kept);

}  // namespace meshprep::detail
