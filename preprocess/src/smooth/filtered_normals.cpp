#include "smooth/filtered_normals.h"

#include "meshprep/core/mesh_patches.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace meshprep::detail {
namespace {

Vec3 point(const TriMesh& mesh, TriMesh::VertexHandle v) { return to_eigen(mesh.point(v)); }

}  // namespace

// Creases are found on these normals, not the raw ones: noise alone (a scanned surface's small
// triangles tilt by tens of degrees) does not make a crease.
std::vector<Vec3> filtered_face_normals(const TriMesh& mesh) {
  const std::size_t n = mesh.n_faces();
  std::vector<Vec3> normals(n), centroids(n);
  std::vector<double> areas(n);
  double edge_sum = 0;
  for (const auto e : mesh.edges()) edge_sum += mesh.calc_edge_length(e);
  const double sigma_centre = edge_sum / static_cast<double>(std::max<std::size_t>(mesh.n_edges(), 1));
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    auto corner = mesh.cfv_begin(TriMesh::FaceHandle(static_cast<int>(i)));
    const Vec3 a = point(mesh, *corner), b = point(mesh, *++corner), c = point(mesh, *++corner);
    const Vec3 cross = (b - a).cross(c - a);
    areas[i] = 0.5 * cross.norm();
    normals[i] = areas[i] > 0 ? Vec3(cross.normalized()) : Vec3::Zero();
    centroids[i] = (a + b + c) / 3;
  });
  // The faces around each face (sharing a vertex), in compressed rows, each with its spatial
  // weight (area x the centroid Gaussian), which no round changes. Gathered from the faces of each
  // vertex (compressed rows too) and each face's corners: plain arrays, not circulators.
  std::vector<std::size_t> vertex_first(mesh.n_vertices() + 1, 0);
  for (const auto f : mesh.faces())
    for (const auto v : mesh.fv_range(f)) ++vertex_first[static_cast<std::size_t>(v.idx()) + 1];
  for (std::size_t v = 0; v < mesh.n_vertices(); ++v) vertex_first[v + 1] += vertex_first[v];
  std::vector<int> vertex_faces(vertex_first.back());
  std::vector<std::array<int, 3>> corners(n);
  {
    std::vector<std::size_t> filled(vertex_first.begin(), vertex_first.end() - 1);
    for (const auto f : mesh.faces()) {
      int k = 0;
      for (const auto v : mesh.fv_range(f)) {
        corners[static_cast<std::size_t>(f.idx())][k++] = v.idx();
        vertex_faces[filled[static_cast<std::size_t>(v.idx())]++] = f.idx();
      }
    }
  }
  auto around_face = [&](std::size_t i, std::vector<int>& faces) {
    faces.clear();
    for (const int v : corners[i])
      for (std::size_t k = vertex_first[static_cast<std::size_t>(v)]; k < vertex_first[static_cast<std::size_t>(v) + 1]; ++k)
        if (std::find(faces.begin(), faces.end(), vertex_faces[k]) == faces.end()) faces.push_back(vertex_faces[k]);
  };
  std::vector<std::size_t> first(n + 1, 0);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    thread_local std::vector<int> faces;
    around_face(i, faces);
    first[i + 1] = faces.size();
  });
  for (std::size_t i = 0; i < n; ++i) first[i + 1] += first[i];
  std::vector<int> around(first[n]);
  std::vector<double> spatial(first[n]);
  const double centre_scale = 0.5 / (sigma_centre * sigma_centre);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    thread_local std::vector<int> faces;
    around_face(i, faces);
    for (std::size_t k = 0; k < faces.size(); ++k) {
      const auto j = static_cast<std::size_t>(faces[k]);
      around[first[i] + k] = faces[k];
      spatial[first[i] + k] = areas[j] * std::exp(-centre_scale * (centroids[j] - centroids[i]).squaredNorm());
    }
  });
  constexpr double kSigmaNormal = 0.35;
  constexpr double kNormalScale = 0.5 / (kSigmaNormal * kSigmaNormal);
  constexpr int kIterations = 5;
  std::vector<Vec3> next(n);
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
      Vec3 sum = Vec3::Zero();
      for (std::size_t k = first[i]; k < first[i + 1]; ++k) {
        const Vec3& normal = normals[static_cast<std::size_t>(around[k])];
        sum += spatial[k] * std::exp(-kNormalScale * (normal - normals[i]).squaredNorm()) * normal;
      }
      next[i] = sum.norm() > 0 ? Vec3(sum.normalized()) : normals[i];
    });
    normals.swap(next);
  }
  return normals;
}

std::vector<char> crease_edges(const TriMesh& mesh, const std::vector<Vec3>& normals, double cos_limit) {
  std::vector<char> crease(mesh.n_edges(), 0);
  const FacePatches patches(mesh);
  tbb::parallel_for(std::size_t(0), mesh.n_edges(), [&](std::size_t i) {
    const TriMesh::EdgeHandle e(static_cast<int>(i));
    if (mesh.is_boundary(e)) return;
    if (patches.border(e)) {  // a patch border is kept as a crease
      crease[i] = 1;
      return;
    }
    const auto f0 = mesh.face_handle(mesh.halfedge_handle(e, 0)), f1 = mesh.face_handle(mesh.halfedge_handle(e, 1));
    crease[i] = normals[static_cast<std::size_t>(f0.idx())].dot(normals[static_cast<std::size_t>(f1.idx())]) < cos_limit;
  });
  return crease;
}

}  // namespace meshprep::detail
