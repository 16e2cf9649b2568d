#pragma once
// The per-format tetrahedral mesh readers behind read_tet_mesh (import.cpp), their in-memory entry
// points (the fuzz targets in fuzz/ call them) and what they share. A format reader only parses:
// it turns the file's numbering into 0-based point indices (checked to be in range) and returns
// what the file lists; read_tet_mesh_from_bytes then checks and completes the mesh once for every
// format (assemble_tet_mesh). Every problem is an InvalidInput "<name>: <where>: <problem>".

#include "meshprep/fem/import.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace meshprep::detail {

enum class TetFormat { Gmsh, Vtu, VtkLegacy, Medit };

/// A file's content as listed, before the shared checks.
struct TetFileContent {
  std::string format;              ///< TetReadReport::format
  std::vector<Vec3> points;        ///< as read (finiteness is checked later)
  std::vector<Tetrahedron> tets;   ///< indices < points.size(), any orientation
  std::vector<int> tet_regions;    ///< one per tet, as in the file (0 = none)
  std::vector<Triangle> triangles; ///< indices < points.size()
  std::vector<int> triangle_tags;  ///< one per triangle, as in the file (0 = none)
  /// Second-order files: the mid-edge nodes of each 10-node tet in kTetEdges' order (readers of
  /// another order permute) and of each 6-node triangle ((0,1) (1,2) (2,0)), one row per element
  /// of that kind read; empty when the file has none. A file that mixes linear and second-order
  /// elements of a kind is refused by assemble_tet_mesh (the row counts differ).
  std::vector<TetEdgeNodes> tet_edge_nodes;
  std::vector<std::array<std::uint32_t, 3>> triangle_edge_nodes;
  std::size_t elements_ignored = 0;
  TagNames region_names, triangle_names;  ///< names the file gives its tags (Gmsh physical names, XDMF <Information>)
  std::string points_file;  ///< names the points in messages when they are in another file (TetGen's .node)
};

TetFileContent read_gmsh(const std::string& name, std::string_view data);
TetFileContent read_vtu(const std::string& name, std::string_view data);
TetFileContent read_vtk_legacy(const std::string& name, std::string_view data);
TetFileContent read_medit(const std::string& name, std::string_view data);

/// The texts of a TetGen mesh and the names that messages give them: each file's own, and
/// `mesh_name` (the path given, .node or .ele) for problems of the mesh as a whole.
struct TetgenTexts {
  std::string mesh_name, node_name, ele_name, face_name;
  std::string_view node, ele;
  std::optional<std::string_view> face;  ///< the .face file is optional
};
TetFileContent read_tetgen(const TetgenTexts& texts);

/// An XDMF file's XML `data` (named `name` in messages) with the heavy data it names: HDF5 files
/// are opened relative to `folder` (empty: the working directory); Format="XML" data is read from
/// `data` itself.
TetFileContent read_xdmf(const std::string& name, std::string_view data, const std::string& folder);

/// read_tet_mesh on a .vtu file, with the boundary faces, tags and names of the x_boundary.vtu
/// beside it when that is meshprep's (import_vtu.cpp).
TetMesh read_vtu_file(const std::string& path, TetReadReport* report);

/// read_tet_mesh on an .xdmf file (and the HDF5 files it names).
TetMesh read_xdmf_file(const std::string& path, TetReadReport* report);

/// The checks and completions every format shares (see import.h): no tets, non-finite points,
/// repeated corners, duplicate tets, faces of three tets, stray triangles and negative tags are
/// refused; tets are turned positive, regions and tags 0 become 1, the boundary is completed.
/// `name` names the input in messages; `report` (may be null) receives the counts.
TetMesh assemble_tet_mesh(TetFileContent content, const std::string& name, TetReadReport* report);

/// Splits elements of N + M nodes into their N corners and M mid-edge nodes (appended to
/// `corners` and `nodes`).
template <std::size_t N, std::size_t M>
void split_nodes(const std::vector<std::array<std::uint32_t, N + M>>& elements, std::vector<std::array<std::uint32_t, N>>& corners,
                 std::vector<std::array<std::uint32_t, M>>& nodes) {
  for (const auto& element : elements) {
    std::array<std::uint32_t, N> c;
    std::array<std::uint32_t, M> m;
    for (std::size_t k = 0; k < N; ++k) c[k] = element[k];
    for (std::size_t k = 0; k < M; ++k) m[k] = element[N + k];
    corners.push_back(c);
    nodes.push_back(m);
  }
}

/// read_tet_mesh on a file already in memory, in the given format (`name` names it in messages;
/// nothing touches the disk).
TetMesh read_tet_mesh_from_bytes(std::string_view bytes, TetFormat format, const std::string& name,
                                 TetReadReport* report = nullptr);

/// read_tet_mesh on TetGen texts already in memory.
TetMesh read_tet_mesh_from_texts(const TetgenTexts& texts, TetReadReport* report = nullptr);

/// A region or boundary tag read as a 64-bit integer, as an int. \throws InvalidInput
/// "<name>: <where><what> <value> does not fit in an int" when it does not.
int tag_from_file(const std::string& name, const std::string& where, const char* what, std::int64_t value);

/// A region or boundary tag stored as a real (a TetGen attribute, a VTK array of any type) as an
/// int, if it is an integer that fits in one.
std::optional<int> integral_tag(double value);

/// A number read from a file, for a message: as an integer when it is one ("12", "1.5", "nan").
std::string number_text(double value);

/// Whether `number` is in a node numbering that starts at `first` and has `count` nodes.
inline bool in_numbering(std::int64_t number, std::int64_t first, std::size_t count) {
  return number >= first && static_cast<std::uint64_t>(number - first) < count;
}

/// \throws InvalidInput "<name>: <where><element> <ordinal> references node <number>, but the nodes
/// are numbered <first> to <last>" (`element` is "tetrahedron", "triangle", "cell", ...).
[[noreturn]] void fail_node_reference(const std::string& name, const std::string& where, const char* element,
                                      std::size_t ordinal, std::int64_t number, std::int64_t first, std::size_t count);

}  // namespace meshprep::detail
