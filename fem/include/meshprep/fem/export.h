#pragma once
/// \file export.h
/// Writing tetrahedral meshes in the formats solvers read. The format follows the extension
/// (case-insensitive):
///
/// | extension | format | tags |
/// | --- | --- | --- |
/// | .msh | Gmsh 4.1 (default) or 2.2, ASCII or binary | physical groups named by region_names and boundary_names (`region_<r>`, `boundary_<t>` where a tag has no name) |
/// | .vtu | VTK XML unstructured grid, binary (zlib, appended) or ASCII; the tets, and the boundary faces in a sibling `<stem>_boundary.vtu` | cell data `region` (tets), `patch` (faces); names in FieldData, see below |
/// | .vtk | VTK legacy unstructured grid (ASCII 3.0), tets only | cell data `region` |
/// | .mesh | Medit (INRIA), MeshVersionFormatted 2 | references on tetrahedra (region) and triangles (tag) |
/// | .node | TetGen .node/.ele/.face (siblings derived from the name) | attribute on .ele, marker on .face |
/// | .inp | Abaqus/CalculiX, C3D4 | ELSET per region; per boundary tag an NSET (its nodes), an ELSET (the tets with a face on it) and an element-face *SURFACE; see below |
/// | .xdmf | XDMF 3 + HDF5 (sibling .h5), dolfinx's XDMFFile layout | grids `facet_tags`, `cell_tags`; names as `<Information>` |
///
/// Node and element numbers are 1-based (0-based point ids in the VTK formats and XDMF); tet t is element
/// t + 1 where a format numbers elements. Coordinates are written with round-trip precision, but
/// in .inp: CalculiX reads at most 20 characters a field, so a coordinate whose shortest
/// round-trip form is longer (up to 24: "-1.2345678901234567e-100") is written with the most
/// significant digits that fit (at least 13), and TetExportReport says by how much it moved.
///
/// Names in .inp: a region's ELSET is its name in TetMesh::region_names, else `REGION_<r>`; a
/// boundary tag named in TetMesh::boundary_names gives its name to its NSET and *SURFACE and
/// `<name>_TETS` to its ELSET (CalculiX 2.20 crashes on a *DSLOAD on a surface that shares its name
/// with an element set); an unnamed tag keeps `BOUNDARY_<t>` (NSET, ELSET) and `SURF_<t>`
/// (*SURFACE), as decks written before names had them.
///
/// .vtu: `x.vtu` holds the tets with the Int32 cell data `region` and each tet's quality (Float64
/// `min_dihedral_deg`, `max_dihedral_deg`, `radius_edge_ratio`, `scaled_jacobian`); `x_boundary.vtu`
/// holds the boundary faces (outward triangles) on the points they use, with the Int32 cell data
/// `patch` (the boundary tag) and the Int64 point data `mesh_point_id` (the point's 0-based index
/// in x.vtu). Each file's FieldData names its tags in use: one Int32 array per name holding [tag,
/// dimension] (3 for a region, 2 for a patch; default names `region_<r>`, `boundary_<t>`), which
/// meshio reads as field_data and ParaView lists. read_tet_mesh reads the faces, tags and names
/// back from x_boundary.vtu.
///
/// Every tet is written positively oriented in each format's own node order. Writes are atomic
/// (a temporary file renamed into place; for .node all three files, for .xdmf and .vtu both, are
/// written before renaming).

#include "meshprep/fem/tet_mesh.h"

#include <cstddef>
#include <string>
#include <vector>

namespace meshprep {

enum class MshVersion { V41, V22 };

/// How the numbers are stored. Each format has its default: binary for .vtu (zlib-compressed
/// appended data, as ParaView writes) and .xdmf (HDF5), ASCII for the others. `binary` asks for
/// binary data where the default is ASCII (.msh), `ascii` for ASCII where it is binary (.vtu);
/// asking a format for what it cannot store (binary .vtk, .mesh, .node, .inp; ASCII .xdmf), or for
/// both, is refused (check_tet_export_options).
struct TetExportOptions {
  MshVersion msh_version = MshVersion::V41;  ///< .msh only
  bool binary = false;                       ///< binary .msh (.vtu and .xdmf are binary anyway)
  bool ascii = false;                        ///< ASCII .vtu (the other text formats are ASCII anyway)
};

/// The files write_tet_mesh writes for `path`: `path` itself, and its siblings for .node (.ele,
/// .face), .xdmf (.h5) and .vtu (<stem>_boundary.vtu); `path` alone for any other extension.
std::vector<std::string> tet_mesh_files(const std::string& path);

/// Checks that the format of `path` can store what `options` ask: InvalidInput "<path>: ..." naming
/// the format that cannot be binary (or ASCII) otherwise, and for `binary` and `ascii` together.
/// write_tet_mesh checks it first; a command calls it before its work, to refuse at once.
void check_tet_export_options(const std::string& path, const TetExportOptions& options);

/// What write_tet_mesh had to give up to fit the format. Only .inp rounds (see above).
struct TetExportReport {
  std::size_t rounded_coordinates = 0;  ///< coordinates written with fewer digits than a round trip needs
  double max_relative_rounding = 0;     ///< the largest |written - exact| / |exact| among them (0 when none)
};

/// Write `mesh` to `path` (format from the extension).
/// \param report if not null, receives what the format made the writer round.
/// \throws InvalidInput for an unknown extension (the message lists the supported ones), or a
///         malformed mesh (no tets, per-element arrays of the wrong size, an index out of range or
///         repeated within an element, a region or tag < 1, a name against patch_names.h's rule,
///         a non-finite coordinate, a tet flat to rounding or inverted (certainly_positive,
///         tet_quality.h: no solver can take it); for .inp also a boundary face that is not an outward face of
///         any tet, or one name, case aside, for two node sets or for two of the element sets and
///         surfaces); options the format cannot honour (check_tet_export_options);
///         IoError if a file cannot be written (nothing is left behind).
void write_tet_mesh(const TetMesh& mesh, const std::string& path, const TetExportOptions& options = {},
                    TetExportReport* report = nullptr);

}  // namespace meshprep
