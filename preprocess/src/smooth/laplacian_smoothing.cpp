#include "smooth/laplacian_smoothing.h"

#include "meshprep/core/mesh_patches.h"

#include <OpenMesh/Tools/Smoother/JacobiLaplaceSmootherT.hh>

#include <vector>

namespace meshprep {
namespace {

void uniform_laplacian_step(TriMesh& mesh, double factor) {
  std::vector<TriMesh::Point> moved(mesh.n_vertices());
  const FacePatches patches(mesh);
  for (const auto v : mesh.vertices()) {
    moved[static_cast<std::size_t>(v.idx())] = mesh.point(v);
    if (mesh.is_boundary(v) || mesh.is_isolated(v) || on_patch_border(patches, mesh, v)) continue;
    TriMesh::Point mean(0, 0, 0);
    int count = 0;
    for (const auto u : mesh.vv_range(v)) {
      mean += mesh.point(u);
      ++count;
    }
    moved[static_cast<std::size_t>(v.idx())] += factor * (mean / count - mesh.point(v));
  }
  for (const auto v : mesh.vertices()) mesh.set_point(v, moved[static_cast<std::size_t>(v.idx())]);
}

}  // namespace

void taubin_smooth(TriMesh& mesh, std::size_t iterations) {
  for (std::size_t i = 0; i < iterations; ++i) {
    uniform_laplacian_step(mesh, 0.5);
    uniform_laplacian_step(mesh, -0.53);
  }
}

void laplace_smooth(TriMesh& mesh, std::size_t iterations) {
  // OpenMesh's smoother leaves locked vertices where they are: the patch borders stay.
  const FacePatches patches(mesh);
  std::vector<TriMesh::VertexHandle> locked;
  for (const auto v : mesh.vertices())
    if (!mesh.status(v).locked() && on_patch_border(patches, mesh, v)) {
      mesh.status(v).set_locked(true);
      locked.push_back(v);
    }
  OpenMesh::Smoother::JacobiLaplaceSmootherT<TriMesh> smoother(mesh);
  smoother.initialize(OpenMesh::Smoother::JacobiLaplaceSmootherT<TriMesh>::Tangential_and_Normal,
                      OpenMesh::Smoother::JacobiLaplaceSmootherT<TriMesh>::C0);
  smoother.smooth(static_cast<unsigned int>(iterations));
  for (const auto v : locked) mesh.status(v).set_locked(false);
}

}  // namespace meshprep
