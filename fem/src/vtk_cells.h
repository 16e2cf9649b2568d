#pragma once
// What the two VTK readers (import_vtu.cpp, import_vtk.cpp) share: the value types of data
// arrays, the names of region arrays, and turning VTK cells into tets and triangles.

#include "importers.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace meshprep::detail {

enum class VtkType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64 };

std::size_t size_of(VtkType type);

/// The `count` values of `type` stored at `bytes` (at least count * size_of(type) of them) in the
/// given byte order, as doubles (exact for every integer below 2^53, which covers every index).
std::vector<double> load_values(std::string_view bytes, VtkType type, std::size_t count, bool little_endian);

/// The rank of a cell-data array's name among the region arrays (region, gmsh:physical,
/// CellEntityIds, medit:ref, tetgen:ref, patch (meshprep's boundary tags): 0, 1, ...), or -1 if it
/// is not one.
int region_array_rank(std::string_view name);

/// The cells of a VTK piece. Cell c's point ids are connectivity[offsets[c - 1] .. offsets[c]]
/// (offsets[-1] = 0); regions is empty or has one value per cell.
struct VtkCells {
  std::vector<double> types, offsets, connectivity, regions;
};

/// Adds the tetrahedra (cell type 10, or 24 with mid-edge nodes) and triangles (5, or 22) of
/// `cells` to `content`, their point ids
/// shifted by `first_point` (the points of the earlier pieces); lower-dimensional cells are counted
/// in elements_ignored; other volume cells and unknown types are refused.
/// \throws InvalidInput naming `name` for inconsistent arrays, an id out of [0, num_points) or
///         not an integer, a region that is not an integer.
void add_vtk_cells(TetFileContent& content, const VtkCells& cells, std::size_t first_point, std::size_t num_points,
                   const std::string& name);

}  // namespace meshprep::detail
