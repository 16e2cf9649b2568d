#pragma once
/// \file export.h
/// Writing tetrahedral meshes in the formats solvers read. The format follows the extension
/// (case-insensitive):
///
/// | extension | format | tags |
/// | --- | --- | --- |
/// | .msh | Gmsh 4.1 (default) or 2.2, ASCII or binary | physical groups named by region_names and boundary_names (`region_<r>`, `boundary_<t>` where a tag has no name) |
/// | .vtu | VTK XML unstructured grid (ASCII), tets only | cell data `region` (Int32) |
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
/// Every tet is written positively oriented in each format's own node order. Writes are atomic
/// (a temporary file renamed into place; for .node all three files, for .xdmf both, are written
/// before renaming).

#include "meshprep/fem/tet_mesh.h"

#include <cstddef>
#include <string>

namespace meshprep {

enum class MshVersion { V41, V22 };

struct TetExportOptions {
  MshVersion msh_version = MshVersion::V41;  ///< .msh only
  bool binary = false;                       ///< .msh only
};

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
///         a non-finite coordinate; for .inp also a boundary face that is not an outward face of
///         any tet, or one name, case aside, for two node sets or for two of the element sets and
///         surfaces);
///         IoError if a file cannot be written (nothing is left behind).
void write_tet_mesh(const TetMesh& mesh, const std::string& path, const TetExportOptions& options = {},
                    TetExportReport* report = nullptr);

}  // namespace meshprep
