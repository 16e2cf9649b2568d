// Conversions between the halfedge mesh and the indexed triangle soup.
#include "meshprep/core/mesh.h"
#include "meshprep/core/mesh_patches.h"
#include "meshprep/core/soup_view.h"

#include "meshprep/core/errors.h"

#include <OpenMesh/Core/System/omstream.hh>

#include <limits>

namespace meshprep {
namespace {

// Silences OpenMesh's error stream (add_face reports "complex edge" there) while alive.
class SilencedOmerr {
 public:
  SilencedOmerr() : was_enabled_(omerr().is_enabled()) { omerr().disable(); }
  ~SilencedOmerr() {
    if (was_enabled_) omerr().enable();
  }
  SilencedOmerr(const SilencedOmerr&) = delete;
  SilencedOmerr& operator=(const SilencedOmerr&) = delete;

 private:
  bool was_enabled_;
};

}  // namespace

namespace {

// The faces of `mesh` not deleted, in index order, each with its corners from its halfedge on,
// numbered by `renumber(vertex index)` (shared by soup_from_mesh and MeshSoupView, which must agree).
template <class Renumber>
std::vector<Triangle> triangles_of(const TriMesh& mesh, const Renumber& renumber) {
  std::vector<Triangle> triangles;
  triangles.reserve(mesh.n_faces());
  for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
    const TriMesh::FaceHandle fh(static_cast<int>(f));
    if (mesh.has_face_status() && mesh.status(fh).deleted()) continue;
    TriMesh::HalfedgeHandle he = mesh.halfedge_handle(fh);
    Triangle triangle{};
    for (std::uint32_t& corner : triangle) {
      corner = renumber(mesh.to_vertex_handle(he).idx());
      he = mesh.next_halfedge_handle(he);
    }
    triangles.push_back(triangle);
  }
  return triangles;
}

bool has_deleted_vertex(const TriMesh& mesh) {
  if (!mesh.has_vertex_status()) return false;
  for (std::size_t v = 0; v < mesh.n_vertices(); ++v)
    if (mesh.status(TriMesh::VertexHandle(static_cast<int>(v))).deleted()) return true;
  return false;
}

}  // namespace

TriangleSoup soup_from_mesh(const TriMesh& mesh) {
  constexpr std::uint32_t unused = std::numeric_limits<std::uint32_t>::max();
  TriangleSoup soup;
  std::vector<std::uint32_t> new_index(mesh.n_vertices(), unused);
  soup.points.reserve(mesh.n_vertices());
  for (std::size_t v = 0; v < mesh.n_vertices(); ++v) {
    const TriMesh::VertexHandle vh(static_cast<int>(v));
    if (mesh.has_vertex_status() && mesh.status(vh).deleted()) continue;
    new_index[v] = static_cast<std::uint32_t>(soup.points.size());
    soup.points.push_back(to_eigen(mesh.point(vh)));
  }
  soup.triangles = triangles_of(mesh, [&](int v) {
    const std::uint32_t corner = new_index[static_cast<std::size_t>(v)];
    if (corner == unused) throw Error("soup_from_mesh: a face uses a deleted vertex");
    return corner;
  });
  const FacePatches patches(mesh);
  if (patches.present()) {
    soup.patches.reserve(soup.triangles.size());
    for (const TriMesh::FaceHandle f : mesh.faces()) soup.patches.push_back(patches.of(f));  // skips deleted faces
    soup.patch_names = patch_names(mesh);
  }
  return soup;
}

MeshSoupView::MeshSoupView(const TriMesh& mesh) {
  if (has_deleted_vertex(mesh)) {  // rare (before garbage collection): the soup's numbering, on a copy
    TriangleSoup soup = soup_from_mesh(mesh);
    compacted_ = std::move(soup.points);
    triangles_ = std::move(soup.triangles);
    points_ = PointSpan(compacted_);
    return;
  }
  triangles_ = triangles_of(mesh, [](int v) { return static_cast<std::uint32_t>(v); });
  points_ = PointSpan(mesh.points(), mesh.n_vertices());
}

TriMesh mesh_from_soup(const TriangleSoup& soup, MeshBuildReport* report) {
  TriMesh mesh;
  mesh.reserve(soup.points.size(), soup.triangles.size() * 3 / 2, soup.triangles.size());
  std::vector<TriMesh::VertexHandle> vertices;
  vertices.reserve(soup.points.size());
  for (const Vec3& p : soup.points) vertices.push_back(mesh.add_vertex(to_openmesh(p)));

  if (report) report->dropped_faces.clear();
  if (!soup.patches.empty() && soup.patches.size() != soup.triangles.size())
    throw InvalidInput("mesh_from_soup: " + std::to_string(soup.patches.size()) + " patches for " +
                       std::to_string(soup.triangles.size()) + " triangles");
  std::vector<int> patches;  // of the faces added
  const SilencedOmerr silenced;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    for (const std::uint32_t index : t) {
      if (index >= vertices.size()) {
        throw InvalidInput("mesh_from_soup: triangle " + std::to_string(f) + " uses vertex " + std::to_string(index) +
                           " of " + std::to_string(vertices.size()));
      }
    }
    // OpenMesh asserts (or corrupts the mesh) on a repeated vertex, so such faces never reach it.
    const bool repeats = t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
    const bool added = !repeats && mesh.add_face(vertices[t[0]], vertices[t[1]], vertices[t[2]]).is_valid();
    if (!added && report) report->dropped_faces.push_back(f);
    if (added && !soup.patches.empty()) patches.push_back(soup.patches[f]);
  }
  if (!soup.patches.empty()) set_face_patches(mesh, patches, soup.patch_names);
  return mesh;
}

}  // namespace meshprep
