#pragma once
/// \file mesh.h
/// The mesh types shared by every module: an OpenMesh triangle mesh with double coordinates
/// (for the processing stages) and a plain indexed triangle soup (exactly what a file holds,
/// used by the quality module so that its topology checks see the file as written).

// OpenMesh's VectorT leaves its coordinates uninitialized, so GCC 12 -O2 warns (maybe-uninitialized)
// inside OpenMesh's property containers in every file that builds a mesh; not our code.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <OpenMesh/Core/Geometry/VectorT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products on Vec3

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace meshprep {

/// OpenMesh traits: double-precision points and normals, face/vertex status for deletion.
struct MeshTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  VertexAttributes(OpenMesh::Attributes::Status);
  EdgeAttributes(OpenMesh::Attributes::Status);
  HalfedgeAttributes(OpenMesh::Attributes::PrevHalfedge);
  FaceAttributes(OpenMesh::Attributes::Status | OpenMesh::Attributes::Normal);
};

/// Halfedge triangle mesh used by the processing stages (simplify, smooth, enhance).
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<std::uint32_t, 3>;

/// The names of tags (boundary patches, regions) by tag, each >= 1. A tag may have no name; the
/// writers then use a default (patch_names.h, tag_name). Names follow patch_names.h's rule.
using TagNames = std::map<int, std::string>;

/// Indexed triangles exactly as read (no vertex merging, no dropped faces).
/// Invariants: every index is < points.size(); `patches` is empty or holds one tag >= 1 per
/// triangle.
struct TriangleSoup {
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
  /// The boundary patch of each triangle: a named set of faces where a solver fixes, loads or
  /// heats the part (patch_names.h). Empty when the surface has none.
  std::vector<int> patches = {};
  TagNames patch_names = {};  ///< the names of the tags in `patches`
};

/// The soup of a halfedge mesh (deleted elements skipped, vertices renumbered densely).
TriangleSoup soup_from_mesh(const TriMesh& mesh);

/// Result of building a halfedge mesh from a soup: the faces OpenMesh refused to add.
struct MeshBuildReport {
  /// Indices (into soup.triangles) of faces that could not be added because they would make an
  /// edge or vertex non-manifold ("complex edge" in OpenMesh) or repeat a vertex. They are not in
  /// the mesh; a caller must report them, never drop them silently.
  std::vector<std::size_t> dropped_faces;
};

/// Build a halfedge mesh from a soup; faces OpenMesh cannot represent are listed in `report`.
TriMesh mesh_from_soup(const TriangleSoup& soup, MeshBuildReport* report = nullptr);

/// Why mesh_from_soup could not add face `face` of `soup`, as a phrase that names it: "face 12
/// has two corners at vertex 0", "face 12 repeats face 3", "face 12 makes the edge 0-1 non-manifold (3
/// faces share it)", "face 5 is oriented against face 2 (both run from vertex 1 to 3)" or "face 4
/// makes vertex 0 non-manifold (2 fans of faces meet there)". O(faces).
std::string dropped_face_problem(const TriangleSoup& soup, std::size_t face);

/// dropped_face_problem of the first face `report` lists, and how many more it lists; empty if none.
std::string dropped_faces_problem(const TriangleSoup& soup, const MeshBuildReport& report);

inline Vec3 to_eigen(const OpenMesh::Vec3d& p) { return {p[0], p[1], p[2]}; }
inline OpenMesh::Vec3d to_openmesh(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

}  // namespace meshprep
