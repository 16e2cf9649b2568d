#pragma once
// numpy arrays to meshprep's mesh types and back. In: each array is checked (dtype, shape,
// C-contiguity, finite points, indices in range, not empty) and copied once into the mesh's own
// storage; anything else raises InputError naming the argument. Out: read-only views of the mesh's
// storage, kept alive by the Python object that owns the mesh (no copy).

#include "meshprep/core/mesh.h"
#include "meshprep/fem/tet_mesh.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <string>

namespace meshprep::python {

namespace py = pybind11;

/// A Surface: a triangle soup, shared so that the arrays handed out keep it alive.
struct Surface {
  std::shared_ptr<TriangleSoup> soup;
};

/// A TetMesh, shared likewise.
struct Tets {
  std::shared_ptr<TetMesh> mesh;
};

/// (n, 3) float64 points: \throws InvalidInput "<what>: ..." for any other dtype, shape or layout,
/// NaN or infinity, or none at all.
std::vector<Vec3> points_from_array(const py::handle& array, const std::string& what);

/// Surface(points, faces, patches=None, patch_names=None).
Surface surface_from_arrays(const py::handle& points, const py::handle& faces, const py::handle& patches,
                            const py::handle& patch_names);

/// TetMesh(points, tets, boundary_faces=None, patches=None, patch_names=None): the boundary is the
/// tets' own (tet_boundary.h) with tag 1 when not given.
Tets tets_from_arrays(const py::handle& points, const py::handle& tets, const py::handle& boundary_faces,
                      const py::handle& patches, const py::handle& patch_names);

/// A read-only (n, 3) float64 view of `points`, alive as long as `owner`.
py::array points_view(const std::vector<Vec3>& points, const py::handle& owner);

/// A read-only (n, K) uint32 view of `rows` (triangles, tets), alive as long as `owner`.
template <std::size_t K>
py::array index_view(const std::vector<std::array<std::uint32_t, K>>& rows, const py::handle& owner);

/// A read-only (n,) int32 view of `tags`, alive as long as `owner`.
py::array tags_view(const std::vector<int>& tags, const py::handle& owner);

/// {tag: name}.
py::dict names_dict(const TagNames& names);

}  // namespace meshprep::python
