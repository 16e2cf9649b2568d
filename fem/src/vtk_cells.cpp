// VTK cell types and data array values ("VTK File Formats",
// https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html; the cell type numbers are
// those of vtkCellType.h).
#include "vtk_cells.h"

#include "byte_order.h"
#include "readers.h"

#include <cmath>
#include <iterator>

namespace meshprep::detail {
namespace {

// The cells read: linear and quadratic triangles and tets. A quadratic cell lists its corners,
// then its mid-edge nodes: VTK_QUADRATIC_TRIANGLE (22) those of (0,1) (1,2) (2,0),
// VTK_QUADRATIC_TETRA (24) those of (0,1) (1,2) (2,0) (0,3) (1,3) (2,3), kTetEdges' order
// (vtkQuadraticTriangle's and vtkQuadraticTetra's documentation).
struct ReadCell {
  int id;
  std::size_t points;
  bool tet;
  const char* name;
};

constexpr ReadCell read_cells[] = {
    {5, 3, false, "triangle"}, {22, 6, false, "quadratic triangle"}, {10, 4, true, "tetrahedron"}, {24, 10, true, "quadratic tetrahedron"}};

const ReadCell* find_read_cell(double id) {
  for (const ReadCell& cell : read_cells)
    if (cell.id == id) return &cell;
  return nullptr;
}

struct CellType {
  int id;
  int dimension;
  const char* name;
};

const CellType cell_types[] = {
    {0, 0, "empty cell"},           {1, 0, "vertex"},
    {2, 0, "poly-vertex"},          {3, 1, "line"},
    {4, 1, "poly-line"},            {5, 2, "triangle"},
    {6, 2, "triangle strip"},       {7, 2, "polygon"},
    {8, 2, "pixel"},                {9, 2, "quad"},
    {10, 3, "tetrahedron"},         {11, 3, "voxel"},
    {12, 3, "hexahedron"},          {13, 3, "wedge"},
    {14, 3, "pyramid"},             {15, 3, "pentagonal prism"},
    {16, 3, "hexagonal prism"},     {21, 1, "quadratic edge"},
    {22, 2, "quadratic triangle"},  {23, 2, "quadratic quad"},
    {24, 3, "quadratic tetrahedron"}, {25, 3, "quadratic hexahedron"},
    {26, 3, "quadratic wedge"},     {27, 3, "quadratic pyramid"},
    {28, 2, "biquadratic quad"},    {29, 3, "triquadratic hexahedron"},
    {34, 2, "biquadratic triangle"}, {35, 1, "cubic line"},
    {36, 2, "quadratic polygon"},   {42, 3, "polyhedron"},
    {68, 1, "Lagrange curve"},      {69, 2, "Lagrange triangle"},
    {70, 2, "Lagrange quadrilateral"}, {71, 3, "Lagrange tetrahedron"},
    {72, 3, "Lagrange hexahedron"}, {73, 3, "Lagrange wedge"},
    {74, 3, "Lagrange pyramid"},    {75, 1, "Bezier curve"},
    {76, 2, "Bezier triangle"},     {77, 2, "Bezier quadrilateral"},
    {78, 3, "Bezier tetrahedron"},  {79, 3, "Bezier hexahedron"},
    {80, 3, "Bezier wedge"},        {81, 3, "Bezier pyramid"},
};

const CellType* find_cell_type(double id) {
  for (const CellType& type : cell_types)
    if (type.id == id) return &type;
  return nullptr;
}

template <class T>
void append_values(std::vector<double>& out, std::string_view bytes, std::size_t count, bool little_endian) {
  for (std::size_t i = 0; i < count; ++i)
    out.push_back(static_cast<double>(load_value<T>(bytes.data() + i * sizeof(T), little_endian)));
}

bool is_index(double value, std::size_t limit) {
  return value >= 0 && value < static_cast<double>(limit) && std::floor(value) == value;
}

}  // namespace

std::size_t size_of(VtkType type) {
  switch (type) {
    case VtkType::Int8:
    case VtkType::UInt8:
      return 1;
    case VtkType::Int16:
    case VtkType::UInt16:
      return 2;
    case VtkType::Int32:
    case VtkType::UInt32:
    case VtkType::Float32:
      return 4;
    case VtkType::Int64:
    case VtkType::UInt64:
    case VtkType::Float64:
      return 8;
  }
  return 8;
}

std::vector<double> load_values(std::string_view bytes, VtkType type, std::size_t count, bool little_endian) {
  std::vector<double> values;
  values.reserve(count);
  switch (type) {
    case VtkType::Int8:
      append_values<std::int8_t>(values, bytes, count, little_endian);
      break;
    case VtkType::UInt8:
      append_values<std::uint8_t>(values, bytes, count, little_endian);
      break;
    case VtkType::Int16:
      append_values<std::int16_t>(values, bytes, count, little_endian);
      break;
    case VtkType::UInt16:
      append_values<std::uint16_t>(values, bytes, count, little_endian);
      break;
    case VtkType::Int32:
      append_values<std::int32_t>(values, bytes, count, little_endian);
      break;
    case VtkType::UInt32:
      append_values<std::uint32_t>(values, bytes, count, little_endian);
      break;
    case VtkType::Int64:
      append_values<std::int64_t>(values, bytes, count, little_endian);
      break;
    case VtkType::UInt64:
      append_values<std::uint64_t>(values, bytes, count, little_endian);
      break;
    case VtkType::Float32:
      append_values<float>(values, bytes, count, little_endian);
      break;
    case VtkType::Float64:
      append_values<double>(values, bytes, count, little_endian);
      break;
  }
  return values;
}

int region_array_rank(std::string_view name) {
  const std::string_view names[] = {"region", "gmsh:physical", "CellEntityIds", "medit:ref", "tetgen:ref", "patch"};
  for (int rank = 0; rank < static_cast<int>(std::size(names)); ++rank)
    if (name == names[rank]) return rank;
  return -1;
}

void add_vtk_cells(TetFileContent& content, const VtkCells& cells, std::size_t first_point, std::size_t num_points,
                   const std::string& name) {
  const std::size_t num_cells = cells.types.size();
  if (cells.offsets.size() != num_cells)
    fail(name, std::to_string(num_cells) + " cell types but " + std::to_string(cells.offsets.size()) + " cell offsets");
  if (!cells.regions.empty() && cells.regions.size() != num_cells)
    fail(name, std::to_string(num_cells) + " cells but " + std::to_string(cells.regions.size()) + " region values");
  std::size_t begin = 0;
  for (std::size_t c = 0; c < num_cells; ++c) {
    const double end_value = cells.offsets[c];
    if (!is_index(end_value, cells.connectivity.size() + 1) || end_value < static_cast<double>(begin))
      fail(name, "cell " + std::to_string(c) + ": offset " + number_text(end_value) + " is not between " +
                     std::to_string(begin) + " and the connectivity's size " + std::to_string(cells.connectivity.size()));
    const auto end = static_cast<std::size_t>(end_value);
    const double type = cells.types[c];
    const ReadCell* cell = find_read_cell(type);
    if (!cell) {
      const CellType* known = find_cell_type(type);
      if (!known) fail(name, "cell " + std::to_string(c) + " has type " + number_text(type) + ", unknown to this reader");
      if (known->dimension == 3)
        fail(name, "cell " + std::to_string(c) + " is a " + known->name + " (type " + std::to_string(known->id) +
                       "); meshprep reads tetrahedra of 4 and 10 nodes (types 10, 24) only");
      ++content.elements_ignored;
      begin = end;
      continue;
    }
    if (end - begin != cell->points)
      fail(name, "cell " + std::to_string(c) + " is a " + cell->name + " with " + std::to_string(end - begin) +
                     " points, not " + std::to_string(cell->points));
    std::uint32_t ids[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (std::size_t k = 0; k < cell->points; ++k) {
      const double id = cells.connectivity[begin + k];
      if (!is_index(id, num_points))
        fail(name, "cell " + std::to_string(c) + " references point " + number_text(id) + ", but the points are " +
                       (num_points == 0 ? std::string("none") : "0 to " + std::to_string(num_points - 1)));
      ids[k] = static_cast<std::uint32_t>(first_point + static_cast<std::size_t>(id));
    }
    std::optional<int> region = 0;
    if (!cells.regions.empty() && !(region = integral_tag(cells.regions[c])))
      fail(name, "cell " + std::to_string(c) + " has region " + number_text(cells.regions[c]) + ", not an integer");
    if (cell->tet) {
      content.tets.push_back({ids[0], ids[1], ids[2], ids[3]});
      content.tet_regions.push_back(*region);
      if (cell->points == 10) content.tet_edge_nodes.push_back({ids[4], ids[5], ids[6], ids[7], ids[8], ids[9]});
    } else {
      content.triangles.push_back({ids[0], ids[1], ids[2]});
      content.triangle_tags.push_back(*region);
      if (cell->points == 6) content.triangle_edge_nodes.push_back({ids[3], ids[4], ids[5]});
    }
    begin = end;
  }
}

}  // namespace meshprep::detail
