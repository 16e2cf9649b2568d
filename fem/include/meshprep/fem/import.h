#pragma once
/// \file import.h
/// Reading tetrahedral meshes written by meshprep or by other tools. The format follows the
/// extension (case-insensitive), as for write_tet_mesh (export.h):
///
/// | extension | format | read | regions from | boundary tags from |
/// | --- | --- | --- | --- | --- |
/// | .msh | Gmsh 4.1 and 2.x (2.0-2.2), ASCII and binary (either byte order) | tets (type 4), triangles (2) | 3D physical group | 2D physical group |
/// | .vtu | VTK XML UnstructuredGrid: ascii, binary (base64), appended raw or base64; UInt32 or UInt64 headers; zlib-compressed; either byte order; pieces joined | tets (cell type 10), triangles (5) | cell data, see below | the same array on triangles |
/// | .vtk | VTK legacy UNSTRUCTURED_GRID 2.0-5.1, ASCII and BINARY | tets (10), triangles (5) | cell data, see below | the same array on triangles |
/// | .mesh | Medit ASCII, MeshVersionFormatted 1-4 | Tetrahedra, Triangles | reference | reference |
/// | .node, .ele | TetGen .node + .ele (+ .face if present), 0- or 1-based | tets | first .ele attribute | .face marker |
/// | .xdmf | XDMF 2/3, data in HDF5 (Format="HDF") or inline ("XML"); dolfinx's and meshprep's layout | the Uniform grid `mesh` (else the first with its own Geometry): Tetrahedron | grid `cell_tags` (tets matched by corners) or a region Attribute | grid `facet_tags` (Triangle + cell Attribute) |
///
/// Names: Gmsh physical names of surfaces and volumes, and XDMF's `<Information Name="<name>"
/// Value="<tag>"/>` in a tag grid (what write_tet_mesh writes; a default name such as `boundary_3`
/// is dropped), become TetMesh::boundary_names and region_names (of the tags the mesh has; names
/// of points and lines are skipped), made to follow patch_names.h's rule (each change in
/// TetReadReport::renamed_names).
///
/// VTK region arrays: the first cell-data array named `region`, `gmsh:physical`, `CellEntityIds`,
/// `medit:ref` or `tetgen:ref` (one component); the same names for a cell Attribute of an XDMF
/// mesh grid.
///
/// What is refused (InvalidInput): higher-order or non-tetrahedral volume elements (10-node tets,
/// hexahedra, prisms, pyramids: meshprep works on linear tets), a file without tetrahedra (a
/// surface: read it with read_soup from a surface format), partitioned Gmsh files, MSH 1 and 4.0,
/// binary Medit (.meshb, not read), XDMF grid collections, mixed topologies and data not in HDF5
/// or inline XML, an XDMF whose HDF5 file or dataset is missing or of another shape than its
/// DataItem says, negative regions or tags, a non-finite coordinate, an index
/// out of range, a tet with a repeated corner, two tets with the same corners, a face shared by
/// more than two tets, a triangle that is not a face of any tet. Points, lines, quadrilaterals
/// and other lower-dimensional elements are skipped (counted in TetReadReport::elements_ignored).
///
/// The result keeps the TetMesh invariants:
/// - points in file order, exactly as written (every exporter writes round-trip precision);
///   Gmsh files: in node-tag order (4.1 lists them grouped by entity);
/// - tets in file order (Gmsh: in element-tag order), positively oriented: a region whose every tet
///   has negative volume has their corners 2 and 3 swapped (a mirrored export; formats differ in
///   convention); a negative tet among positive ones is kept as it is (a tangle:
///   TetReadReport::tets_inverted counts them), and so is a flat tet (volume 0; a quality problem,
///   not a format error);
/// - regions >= 1: a region 0 or no region becomes 1; negative regions are refused;
/// - boundary_faces: every face that belongs to exactly one tet is there, oriented outward (away
///   from its tet). The triangles the file lists come first, in file order, with the file's tag
///   (0 or none becomes 1); the boundary faces the file does not list follow, in tet order, with
///   tag 1. A listed triangle that is a face of two tets (an interface between regions, an
///   internal surface) is kept too, with the file's orientation and tag: boundary_faces is then
///   more than the boundary (TetReadReport::interface_faces counts those; tet_boundary.h gives
///   the boundary alone).
/// A mesh written by write_tet_mesh reads back with the same points, tets, regions, boundary
/// faces and tags (bit for bit; the VTK formats store no boundary faces, so those read back
/// computed, with tag 1).

#include "meshprep/core/patch_names.h"
#include "meshprep/fem/tet_mesh.h"

#include <string>

namespace meshprep {

/// What read_tet_mesh found in a file beyond the mesh itself, so that nothing is lost quietly.
struct TetReadReport {
  std::string path;
  std::string format;                    ///< e.g. "msh 4.1 binary", "vtu appended raw zlib", "vtk 5.1 ascii"
  std::size_t triangles_in_file = 0;     ///< triangles the file lists (each but a duplicate is in boundary_faces)
  std::size_t interface_faces = 0;       ///< of those, faces of two tets (kept with their tags)
  /// Of interface_faces, those inside one region (both tets in it): an internal surface, kept and
  /// written with its tag like the boundary, which a solver may take for a boundary.
  std::size_t internal_faces = 0;
  std::size_t duplicate_triangles = 0;   ///< triangles listed again (the first one's tag is kept)
  std::size_t untagged_boundary_faces = 0;  ///< boundary faces the file does not list (tag 1)
  /// Tets of negative volume in a region where all are (a mirrored region): corners 2 and 3 swapped.
  std::size_t tets_reoriented = 0;
  /// Tets of negative volume among positive ones in their region: left as they are (a tangle, which
  /// the quality report counts as inverted and the verdict refuses).
  std::size_t tets_inverted = 0;
  std::size_t elements_ignored = 0;      ///< points, lines, quadrilaterals, ... skipped
  std::vector<RenamedTag> renamed_names;  ///< region and boundary names changed to follow patch_names.h's rule
};

/// Read a tetrahedral mesh (format from the extension; for TetGen either the .node or the .ele,
/// the siblings are found by name and .face is optional; an .xdmf's HDF5 files are found where
/// its DataItems say, relative to its folder).
/// \param report if not null, receives what the file held beyond the mesh.
/// \throws InvalidInput for an unknown extension (the message lists the supported ones) or a
///         malformed file: one line naming the file, the line or byte where it helps, and the
///         problem; IoError if a file cannot be opened or read.
TetMesh read_tet_mesh(const std::string& path, TetReadReport* report = nullptr);

/// Whether read_tet_mesh reads files with the extension of `path` (.msh .vtu .vtk .mesh .node .ele
/// .xdmf, case-insensitive).
bool is_tet_mesh_path(const std::string& path);

/// The extensions read_tet_mesh reads, as a message lists them (".msh, .vtu, ...").
std::string tet_mesh_extensions();

}  // namespace meshprep
