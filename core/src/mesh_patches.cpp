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

void inherit_split_patches(TriMesh& mesh, TriMesh::VertexHandle m, TriMesh::VertexHandle a, TriMesh::VertexHandle b) {
  const OpenMesh::FPropHandleT<int> handle = patch_property(mesh);
  if (!handle.is_valid()) return;
  for (const auto out : mesh.voh_range(m)) {
    const TriMesh::VertexHandle corner = mesh.to_vertex_handle(out);
    if (corner == a || corner == b || mesh.is_boundary(mesh.edge_handle(out))) continue;
    // The two faces across m-corner are the halves of one face: one kept its patch.
    const TriMesh::FaceHandle f = mesh.face_handle(out), g = mesh.opposite_face_handle(out);
    int& pf = mesh.property(handle, f);
    int& pg = mesh.property(handle, g);
    if (pf == 0) pf = pg;
    if (pg == 0) pg = pf;
  }
}

bool on_patch_border(const FacePatches& patches, const TriMesh& mesh, TriMesh::VertexHandle v) {
  if (!patches.present()) return false;
  int first = 0;
  for (const auto f : mesh.vf_range(v)) {
    if (first == 0) first = patches.of(f);
    else if (patches.of(f) != first) return true;
  }
  return false;
}

TagNames patch_names(const TriMesh& mesh) {
  OpenMesh::MPropHandleT<TagNames> names_handle;
  if (!mesh.get_property_handle(names_handle, kNamesProperty)) return {};
  return mesh.property(names_handle);
}

}  // namespace meshprep
