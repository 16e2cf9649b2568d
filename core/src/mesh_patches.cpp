#include "meshprep/core/mesh_patches.h"

#include "meshprep/core/errors.h"

namespace meshprep {
namespace {

constexpr const char* kPatchProperty = "meshprep:patch";
constexpr const char* kNamesProperty = "meshprep:patch_names";

OpenMesh::FPropHandleT<int> patch_property(const TriMesh& mesh) {
  OpenMesh::FPropHandleT<int> handle;
  mesh.get_property_handle(handle, kPatchProperty);
  return handle;
}

}  // namespace

FacePatches::FacePatches(const TriMesh& mesh) : mesh_(mesh), property_(patch_property(mesh)) {}

bool FacePatches::border(TriMesh::EdgeHandle e) const {
  if (!present()) return false;
  const TriMesh::FaceHandle a = mesh_.face_handle(mesh_.halfedge_handle(e, 0));
  const TriMesh::FaceHandle b = mesh_.face_handle(mesh_.halfedge_handle(e, 1));
  return a.is_valid() && b.is_valid() && of(a) != of(b);
}

void set_face_patches(TriMesh& mesh, const std::vector<int>& patches, const TagNames& names) {
  OpenMesh::FPropHandleT<int> handle = patch_property(mesh);
  OpenMesh::MPropHandleT<TagNames> names_handle;
  mesh.get_property_handle(names_handle, kNamesProperty);
  if (patches.empty()) {
    if (handle.is_valid()) mesh.remove_property(handle);
    if (names_handle.is_valid()) mesh.remove_property(names_handle);
    return;
  }
  if (patches.size() != mesh.n_faces())
    throw Error("set_face_patches: " + std::to_string(patches.size()) + " patches for " +
                std::to_string(mesh.n_faces()) + " faces");
  if (!handle.is_valid()) mesh.add_property(handle, kPatchProperty);
  if (!names_handle.is_valid()) mesh.add_property(names_handle, kNamesProperty);
  for (std::size_t f = 0; f < patches.size(); ++f) mesh.property(handle, TriMesh::FaceHandle(static_cast<int>(f))) = patches[f];
  mesh.property(names_handle) = names;
}

void set_face_patch(TriMesh& mesh, TriMesh::FaceHandle f, int patch) {
  const OpenMesh::FPropHandleT<int> handle = patch_property(mesh);
  if (!handle.is_valid()) throw Error("set_face_patch: the mesh has no patches");
  mesh.property(handle, f) = patch;
}

TagNames patch_names(const TriMesh& mesh) {
  OpenMesh::MPropHandleT<TagNames> names_handle;
  if (!mesh.get_property_handle(names_handle, kNamesProperty)) return {};
  return mesh.property(names_handle);
}

}  // namespace meshprep
