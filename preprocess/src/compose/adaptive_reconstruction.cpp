#include "meshprep/preprocess/compose/adaptive_reconstruction.h"

#include "meshprep/core/finite_points.h"
#include "meshprep/preprocess/simplify/simplify.h"

#include <chrono>

namespace meshprep {

ReconstructResult reconstruct_adaptive(const std::vector<Vec3>& points, const AdaptiveReconstructParams& params) {
  const auto start = std::chrono::steady_clock::now();
  const PartitionOfUnity pu = fit_surface(points, params.reconstruct);
  ReconstructResult result = mesh_surface(pu, params.reconstruct, 2);
  TriMesh mesh = mesh_from_soup(result.mesh);  // manifold by construction (bow ties dropped)
  SimplifyParams simplify_params;
  simplify_params.keep_ratio = 0.25;
  simplify_params.progress = params.progress;
  result.taken_back = simplify(mesh, simplify_params).taken_back;
  result.mesh = soup_from_mesh(mesh);
  result.vertex_variation.clear();
  for (const Vec3& p : result.mesh.points) {
    const Vec3 local = pu.frame().to_local(p);
    result.vertex_variation.push_back(pu.evaluate(local.x(), local.y()).variation);
  }
  result.filled_faces.clear();
  require_finite_points(result.mesh.points, "reconstruct");
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace meshprep
