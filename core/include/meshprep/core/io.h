#pragma once
/// \file io.h
/// Reading and writing surface meshes and point sets. The format follows the file extension
/// (case-insensitive):
///
/// /// | format | read | write | notes | patches (read and written) |
/// | --- | --- | --- | --- | --- |
/// | .off | yes | yes | polygons are fan-triangulated on read | none |
/// | .obj | yes | yes | `v` and `f` records (v, v/t, v/t/n, v//n, negative indices); polygons triangulated | `g` / `o` groups |
/// | .ply | yes | yes | ASCII, binary little and big endian; polygons triangulated; writes per-vertex scalars | face property `patch` (read also `label`, `tag`), names in `comment patch <tag> <name>` |
/// | .stl | yes | yes | ASCII and binary (also binary files whose header starts with "solid"); equal corners merged | ASCII: one `solid <name>` per patch |
/// | .xyz | points | no | `x y z` or `x y z nx ny nz` per line, `#` comments | |
///
/// Patches: a file's groups become the soup's patches (TriangleSoup::patches, tags 1, 2, ... in
/// the order the file names them) only when they split it into two or more: a single name is the
/// part's name. Faces before the first group join the patch "default" (OBJ's own default group).
/// Names are made to follow patch_names.h's rule, each change listed in ReadReport. Writers that
/// hold no patches (OFF, binary STL) drop them.
///
/// Every reader validates what it reads: NaN/Inf coordinates, out-of-range or negative indices,
/// truncated files, element counts that do not match the data and empty files are rejected
/// with an InvalidInput whose message names the file and the problem on one line.
/// Writers are atomic: they write a temporary file beside the target and rename it, so an
/// interrupted or failed run never leaves a half-written file.

#include "meshprep/core/mesh.h"
#include "meshprep/core/patch_names.h"

#include <string>
#include <vector>

namespace meshprep {

/// What a reader saw in the file, so that nothing is lost quietly.
struct ReadReport {
  std::string path;
  std::string format;                   ///< "off", "obj", "ply-ascii", "ply-binary", "stl-ascii", "stl-binary"
  std::size_t faces_in_file = 0;        ///< polygons in the file
  std::size_t polygons_triangulated = 0;  ///< of those, polygons with more than 3 corners (fan-triangulated)
  std::size_t triangles = 0;            ///< triangles after triangulation (soup.triangles.size())
  /// Where the soup's patches came from ("obj groups", "stl solids", "ply face property 'label'"),
  /// or empty when the file names none (or a single one: the part's name, not a patch).
  std::string patches_from;
  std::vector<RenamedTag> renamed_patches;  ///< names changed to follow patch_names.h's rule
};

/// Read a surface mesh as an indexed triangle soup.
/// \throws InvalidInput on malformed content, unknown extension or an empty mesh; IoError if unreadable.
TriangleSoup read_soup(const std::string& path, ReadReport* report = nullptr);

/// A surface as read from a file: the soup as written, the halfedge mesh built from it,
/// and the faces that could not be added to the halfedge mesh (non-manifold, see MeshBuildReport).
struct LoadedMesh {
  TriangleSoup soup;
  TriMesh mesh;
  ReadReport read;
  MeshBuildReport build;
};

/// read_soup + mesh_from_soup.
LoadedMesh load_mesh(const std::string& path);

/// \throws InvalidInput "<path>: <why the first face was dropped>; <stage> needs a manifold,
/// consistently oriented surface (...)" if the halfedge mesh lacks faces of the file (see
/// dropped_faces_problem): `stage` ("simplification") cannot work on what the file holds; and
/// "<path>: no face has a positive area; <stage> needs a surface" when every face is degenerate.
void require_all_faces(const LoadedMesh& loaded, const std::string& stage);

/// A named value per point of a mesh (e.g. the surface variation sigma, see quality/surface_variation.h).
struct VertexScalar {
  std::string name;            ///< one printable ASCII word, not x, y or z
  std::vector<double> values;  ///< one finite value per point, in point order
};

/// Options for writing a mesh.
struct WriteOptions {
  bool binary = false;  ///< PLY and STL: binary instead of ASCII
  /// Per-vertex scalars. Only PLY stores them (`property double NAME` after x, y, z, in this
  /// order); OFF, OBJ and STL have no place for them and drop them, so a caller that must keep
  /// them writes .ply. They are validated whatever the format.
  std::vector<VertexScalar> vertex_scalars;
};

/// Write a halfedge mesh (format from the extension), atomically. Vertex scalars hold one value per
/// vertex that is not deleted, in index order (the numbering of soup_from_mesh).
/// \throws InvalidInput for an unknown extension or invalid vertex scalars; IoError if the file cannot be written.
void write_mesh(const TriMesh& mesh, const std::string& path, const WriteOptions& options = {});

/// Write a soup (format from the extension), atomically. Nothing is written when the input is
/// invalid.
/// \throws InvalidInput for an unknown extension, a non-finite point or an index out of range, a
/// binary STL whose float32 coordinates would make two corners of a triangle one, and
/// for a vertex scalar with an empty, duplicate, non-printable or x/y/z name, a value count other
/// than soup.points.size() or a non-finite value; IoError if the file cannot be written.
void write_soup(const TriangleSoup& soup, const std::string& path, const WriteOptions& options = {});

/// A point set, with normals when every line had six values.
struct PointSet {
  std::vector<Vec3> points;
  std::vector<Vec3> normals;  ///< empty, or one per point
};

/// Read an XYZ point set (any extension but those of the mesh formats, which are refused).
/// \throws InvalidInput for a mesh extension, on a malformed line (named by its number), NaN/Inf, a
/// mix of 3- and 6-column lines, or no points; IoError if unreadable.
PointSet read_points(const std::string& path);

/// The whole content of the input file `path` (symlinks followed). Only a regular file is read: a
/// device, a FIFO, a socket or a folder is refused at once, since it may never end (/dev/zero) or
/// never start (a FIFO nobody writes to). Every reader and the pipeline's configuration read
/// through this.
/// \throws InvalidInput "<path>: not a regular file (a FIFO): ..."; IoError "<path>: cannot open:
/// <reason>" (or "cannot read").
std::string read_input_file(const std::string& path);

/// Lower-case extension without the dot ("off" for "a/B.OFF"); empty if none.
std::string extension_of(const std::string& path);

/// Whether `path` names a surface mesh by its extension (.off, .obj, .ply, .stl: what read_soup
/// reads).
bool is_surface_mesh_path(const std::string& path);

}  // namespace meshprep
