// VTK XML unstructured grids (.vtu, "VTK File Formats",
// https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html), two files:
//
// x.vtu           the tets (VTK_TETRA, cell type 10; VTK_QUADRATIC_TETRA, 24, second-order) with
//                 the region as Int32 cell data "region" and each tet's quality as Float32 cell data
//                 (vtk_cell_quality.h);
// x_boundary.vtu  the boundary faces (VTK_TRIANGLE, 5; VTK_QUADRATIC_TRIANGLE, 22), outward, on the
//                 points they use, with the
//                 boundary tag as Int32 cell data "patch" and, as Int64 point data "mesh_point_id",
//                 each point's 0-based index in x.vtu (which import_vtu.cpp reads them back by).
//
// Each file names its tags in use in its FieldData, one Int32 array per name holding [tag,
// dimension] (3 for a region, 2 for a patch): meshio reads it as field_data {name: [tag, dim]},
// its form for Gmsh's physical names, and ParaView lists it. A tag without a name gets its default
// one (patch_names.h's tag_name: region_<r>, boundary_<t>), as the Gmsh and XDMF writers do.
//
// Data: binary by default, as ParaView writes (appended raw, zlib, vtu_writer.h); ASCII on request
// (TetExportOptions::ascii). Both files are written before either is renamed into place.
//
// Orientation: vtkTetra's points 0,1,2 form a triangle whose right-hand normal points towards
// point 3 - positive volume in TetMesh's sense, so tets are written in their own order.
#include "exporters.h"
#include "vtk_cell_quality.h"
#include "vtu_files.h"
#include "vtu_writer.h"

#include "meshprep/core/atomic_file.h"
#include "meshprep/core/patch_names.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace meshprep::detail {
namespace {

std::vector<VtuTagName> tag_names(const TagNames& names, const std::vector<int>& tags, const char* prefix,
                                  int dimension) {
  std::vector<VtuTagName> named;
  for (const int tag : distinct_tags(tags)) named.push_back({tag_name(names, tag, prefix), tag, dimension});
  return named;
}

// The ids as Int32 when every one fits (half the bytes of Int64, VTK 9's own choice; every VTK
// reader, meshio and import_vtu.cpp take either), else as Int64.
VtuArray index_array(std::string name, const std::vector<std::int64_t>& ids, std::size_t per_line = kVtuValuesPerLine) {
  if (std::all_of(ids.begin(), ids.end(), [](std::int64_t id) { return id <= std::numeric_limits<std::int32_t>::max(); }))
    return vtu_array(std::move(name), std::vector<std::int32_t>(ids.begin(), ids.end()), 1, per_line);
  return vtu_array(std::move(name), ids, 1, per_line);
}

// The cells of `piece`, each of `corners` point ids in `connectivity` and of VTK cell type `type`;
// a cell's offset is where its ids end in `connectivity`.
void set_cells(VtuPiece& piece, const std::vector<std::int64_t>& connectivity, std::size_t corners, std::uint8_t type) {
  std::vector<std::int64_t> offsets(piece.num_cells);
  for (std::size_t c = 0; c < piece.num_cells; ++c) offsets[c] = static_cast<std::int64_t>(corners * (c + 1));
  piece.connectivity = index_array("connectivity", connectivity, corners);
  piece.offsets = index_array("offsets", offsets);
  piece.types = vtu_array("types", std::vector<std::uint8_t>(piece.num_cells, type));
}

VtuArray points_array(const std::vector<Vec3>& points) {
  std::vector<double> xyz;
  xyz.reserve(3 * points.size());
  for (const Vec3& p : points) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  return vtu_array("", xyz, 3, 3);
}

VtuPiece tets_piece(const TetMesh& mesh) {
  VtuPiece piece;
  piece.num_points = mesh.points.size();
  piece.num_cells = mesh.tets.size();
  piece.points = points_array(mesh.points);
  const std::size_t nodes_per_tet = mesh.quadratic() ? 10 : 4;
  std::vector<std::int64_t> connectivity(nodes_per_tet * mesh.tets.size());
  auto id = connectivity.begin();
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    id = std::copy(mesh.tets[t].begin(), mesh.tets[t].end(), id);
    if (mesh.quadratic()) id = std::copy(mesh.tet_edge_nodes[t].begin(), mesh.tet_edge_nodes[t].end(), id);
  }
  set_cells(piece, connectivity, nodes_per_tet, static_cast<std::uint8_t>(vtk_tet_type(mesh)));
  piece.cell_scalars = "region";
  piece.cell_data.push_back(vtu_array("region", std::vector<std::int32_t>(mesh.tet_regions.begin(), mesh.tet_regions.end())));
  const std::vector<TetShape> shapes = tet_shapes(mesh);
  for (const VtkQualityArray& array : kVtkQualityArrays) {
    std::vector<float> values(shapes.size());
    for (std::size_t t = 0; t < shapes.size(); ++t) values[t] = vtk_cell_value(shapes[t].*array.field);
    piece.cell_data.push_back(vtu_array(array.name, values));
  }
  piece.tag_names = tag_names(mesh.region_names, mesh.tet_regions, "region", 3);
  return piece;
}

// The boundary faces on the points they use, in order of first use; a second-order mesh's as
// VTK_QUADRATIC_TRIANGLE (corners, then the nodes of edges (0,1) (1,2) (2,0)).
VtuPiece boundary_piece(const TetMesh& mesh) {
  VtuPiece piece;
  constexpr std::int64_t kUnused = -1;
  std::vector<std::int64_t> local(mesh.points.size(), kUnused);  // mesh point -> its index here
  std::vector<std::int64_t> mesh_point_id, connectivity;
  std::vector<Vec3> points;
  const auto add = [&](std::uint32_t v) {
    if (local[v] == kUnused) {
      local[v] = static_cast<std::int64_t>(points.size());
      points.push_back(mesh.points[v]);
      mesh_point_id.push_back(v);
    }
    connectivity.push_back(local[v]);
  };
  const std::vector<std::array<std::uint32_t, 3>> edge_nodes = boundary_face_edge_nodes(mesh);
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) {
    for (const std::uint32_t v : mesh.boundary_faces[f]) add(v);
    if (mesh.quadratic())
      for (const std::uint32_t v : edge_nodes[f]) add(v);
  }
  piece.num_points = points.size();
  piece.num_cells = mesh.boundary_faces.size();
  piece.point_data.push_back(vtu_array("mesh_point_id", mesh_point_id));
  piece.points = points_array(points);
  set_cells(piece, connectivity, mesh.quadratic() ? 6 : 3,
            static_cast<std::uint8_t>(mesh.quadratic() ? kVtkQuadraticTriangle : kVtkTriangle));
  piece.cell_scalars = "patch";
  piece.cell_data.push_back(vtu_array("patch", std::vector<std::int32_t>(mesh.boundary_tags.begin(), mesh.boundary_tags.end())));
  piece.tag_names = tag_names(mesh.boundary_names, mesh.boundary_tags, "boundary", 2);
  return piece;
}

}  // namespace

// The two writes are nested so that both temporary files are complete before the first rename.
void write_vtu(const TetMesh& mesh, const std::string& path, const TetExportOptions& options) {
  const bool binary = !options.ascii;
  write_file_atomically(
      path,
      [&](std::ostream& tets_out) {
        write_vtu_piece(tets_out, tets_piece(mesh), binary);
        tets_out.flush();
        write_file_atomically(
            vtu_boundary_path(path),
            [&](std::ostream& boundary_out) { write_vtu_piece(boundary_out, boundary_piece(mesh), binary); }, binary);
      },
      binary);
}

}  // namespace meshprep::detail
