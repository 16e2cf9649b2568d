#pragma once
// A VTK XML UnstructuredGrid file (.vtu) of one piece, written from its arrays (export_vtu.cpp
// fills them): ASCII text inside each <DataArray>, or binary as VTK and ParaView write by default,
// appended raw data with each array one zlib-compressed block list (compressor=
// "vtkZLibDataCompressor", header_type="UInt64": [number of blocks, block size, size of the last
// block (0 = a full one), compressed size of each block], then the compressed blocks), little
// endian. import_vtu.cpp reads both back; so do meshio and ParaView.

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace meshprep::detail {

/// Values per line of an ASCII array unless its tuples are lines (points, cells): ParaView's own
/// number; one per line would make the indentation a third of the file.
inline constexpr std::size_t kVtuValuesPerLine = 6;

/// One data array, its values stored little endian.
struct VtuArray {
  std::string name;          ///< empty for the points
  const char* type = "";     ///< "Float64", "Float32", "Int64", "Int32" or "UInt8"
  std::size_t components = 1;
  std::size_t per_line = kVtuValuesPerLine;  ///< values per line of ASCII text
  std::string bytes;
};

/// The array `name` holding `values` (of `components` components; `per_line` values a line in ASCII).
VtuArray vtu_array(std::string name, const std::vector<double>& values, std::size_t components = 1,
                   std::size_t per_line = kVtuValuesPerLine);
VtuArray vtu_array(std::string name, const std::vector<float>& values, std::size_t components = 1,
                   std::size_t per_line = kVtuValuesPerLine);
VtuArray vtu_array(std::string name, const std::vector<std::int64_t>& values, std::size_t components = 1,
                   std::size_t per_line = kVtuValuesPerLine);
VtuArray vtu_array(std::string name, const std::vector<std::int32_t>& values, std::size_t components = 1,
                   std::size_t per_line = kVtuValuesPerLine);
VtuArray vtu_array(std::string name, const std::vector<std::uint8_t>& values, std::size_t components = 1,
                   std::size_t per_line = kVtuValuesPerLine);

/// A tag's name, in the grid's <FieldData>: an Int32 array named by it holding [tag, dimension],
/// the form in which meshio keeps Gmsh's physical names (field_data) and ParaView lists field data.
struct VtuTagName {
  std::string name;
  int tag = 0;
  int dimension = 0;  ///< 2 for a boundary patch, 3 for a region
};

struct VtuPiece {
  std::size_t num_points = 0, num_cells = 0;
  std::vector<VtuArray> point_data;
  VtuArray points;  ///< Float64, 3 components
  VtuArray connectivity, offsets, types;
  std::vector<VtuArray> cell_data;
  std::string cell_scalars;  ///< the CellData's active scalars (its Scalars attribute), if any
  std::vector<VtuTagName> tag_names;
};

/// Writes `piece` as a whole .vtu file, binary (appended, zlib) or ASCII.
void write_vtu_piece(std::ostream& out, const VtuPiece& piece, bool binary);

}  // namespace meshprep::detail
