// VTK legacy unstructured grid .vtk (ASCII, version 3.0), per "VTK File Formats"
// (https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html). Tets only, as VTK_TETRA
// (cell type 10), or VTK_QUADRATIC_TETRA (24) for a second-order mesh (vtk_cell_quality.h), with the
// region as cell data "region" and each tet's quality (tet_quality.h, of the corner tets) as
// float cell data: min_dihedral_deg, max_dihedral_deg, radius_edge_ratio, scaled_jacobian.
//
// Orientation: vtkTetra's points 0,1,2 form a triangle whose right-hand normal points towards
// point 3 - positive volume in TetMesh's sense, so tets are written in their own order.
#include "exporters.h"
#include "text_buffer.h"
#include "vtk_cell_quality.h"

#include "meshprep/core/atomic_file.h"

#include <ostream>
#include <string>
#include <vector>

namespace meshprep::detail {
namespace {

// Legacy format: CELLS lists "4 a b c d" per tet, so its size is 5 T; 0-based point ids ("10 a b
// c d" and six mid-edge nodes for a second-order tet, 11 T).
void write_vtk_legacy_stream(TextBuffer& out, const TetMesh& mesh) {
  out << "# vtk DataFile Version 3.0\n"
      << "meshprep tetrahedral mesh\n"
      << "ASCII\n"
      << "DATASET UNSTRUCTURED_GRID\n"
      << "POINTS " << mesh.points.size() << " double\n";
  for (const Vec3& p : mesh.points) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  const std::size_t nodes_per_cell = mesh.quadratic() ? 10 : 4;
  out << "CELLS " << mesh.tets.size() << ' ' << (nodes_per_cell + 1) * mesh.tets.size() << '\n';
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    out << nodes_per_cell;
    for (const std::uint32_t v : mesh.tets[t]) out << ' ' << v;
    if (mesh.quadratic())
      for (const std::uint32_t v : mesh.tet_edge_nodes[t]) out << ' ' << v;
    out << '\n';
  }
  out << "CELL_TYPES " << mesh.tets.size() << '\n';
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) out << vtk_tet_type(mesh) << '\n';
  out << "CELL_DATA " << mesh.tets.size() << '\n'
      << "SCALARS region int 1\n"
      << "LOOKUP_TABLE default\n";
  for (int region : mesh.tet_regions) out << region << '\n';
  const std::vector<TetShape> shapes = tet_shapes(mesh);
  for (const VtkQualityArray& array : kVtkQualityArrays) {
    out << "SCALARS " << array.name << " float 1\n"
        << "LOOKUP_TABLE default\n";
    for (const TetShape& shape : shapes) out << vtk_cell_value(shape.*array.field) << '\n';
  }
}

}  // namespace

void write_vtk_legacy(const TetMesh& mesh, const std::string& path) {
  write_file_atomically(path, [&](std::ostream& stream) {
    TextBuffer out(stream);
    write_vtk_legacy_stream(out, mesh);
    out.flush();
  });
}

}  // namespace meshprep::detail
