#pragma once
/// \file mesh_patches.h
/// Boundary patches on the halfedge mesh: the patch of each face is an OpenMesh face property and
/// the names a mesh property, so that they travel with the mesh through every stage. OpenMesh keeps
/// a face's properties through a flip, a collapse (of the faces that remain) and garbage
/// collection, and copies them to the new faces of split_copy / split_edge_copy; a stage that adds
/// faces otherwise sets their patch itself. soup_from_mesh and mesh_from_soup carry them.

#include "meshprep/core/mesh.h"

#include <vector>

namespace meshprep {

/// Read access to the patches of a mesh: looks the properties up once.
class FacePatches {
 public:
  explicit FacePatches(const TriMesh& mesh);

  /// Whether the mesh has patches.
  bool present() const { return property_.is_valid(); }
  /// The patch of face f (>= 1), or 0 when the mesh has none.
  int of(TriMesh::FaceHandle f) const { return present() ? mesh_.property(property_, f) : 0; }
  /// Whether e lies between two faces of different patches: a border the stages keep as a feature.
  /// False for an edge on the mesh's boundary and on a mesh without patches.
  bool border(TriMesh::EdgeHandle e) const;

 private:
  const TriMesh& mesh_;
  OpenMesh::FPropHandleT<int> property_;
};

/// Gives every face of `mesh` the patch of the same index in `patches` (one per face, in face
/// index order) and stores `names`. An empty `patches` removes the mesh's patches.
void set_face_patches(TriMesh& mesh, const std::vector<int>& patches, const TagNames& names);

/// Sets the patch of one face (a face a stage added); the mesh must have patches.
void set_face_patch(TriMesh& mesh, TriMesh::FaceHandle f, int patch);

/// After mesh.split(e, m) of the edge a-b: the faces the split added (patch 0, OpenMesh's default)
/// take the patch of the face each was cut from, its neighbour across the edge from m to the
/// corner off a-b. Nothing to do on a mesh without patches.
void inherit_split_patches(TriMesh& mesh, TriMesh::VertexHandle m, TriMesh::VertexHandle a, TriMesh::VertexHandle b);

/// Whether the faces around v lie in more than one patch (v is on a patch border).
bool on_patch_border(const FacePatches& patches, const TriMesh& mesh, TriMesh::VertexHandle v);

/// The names stored with the mesh's patches (empty without patches).
TagNames patch_names(const TriMesh& mesh);

}  // namespace meshprep
