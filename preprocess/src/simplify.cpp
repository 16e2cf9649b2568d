#include "meshprep/preprocess/simplify.h"

#include "meshprep/core/errors.h"

#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <chrono>
#include <cmath>

namespace meshprep {
namespace {

std::size_t target_of(const TriMesh& mesh, const SimplifyParams& params) {
  if (params.target_faces > 0) return params.target_faces;
  if (!(params.keep_ratio > 0 && params.keep_ratio <= 1))
    throw InvalidInput("the ratio of faces kept must be in (0, 1]");
  return static_cast<std::size_t>(std::llround(params.keep_ratio * static_cast<double>(mesh.n_faces())));
}

// Garland & Heckbert 1997 quadrics as OpenMesh implements them; normal flips forbidden.
void decimate_quadric(TriMesh& mesh, std::size_t target) {
  using Decimater = OpenMesh::Decimater::DecimaterT<TriMesh>;
  Decimater decimater(mesh);
  OpenMesh::Decimater::ModQuadricT<TriMesh>::Handle quadric;
  OpenMesh::Decimater::ModNormalFlippingT<TriMesh>::Handle no_flips;
  decimater.add(quadric);
  decimater.add(no_flips);
  decimater.module(quadric).unset_max_err();
  decimater.initialize();
  decimater.decimate_to_faces(0, target);
}

}  // namespace

SimplifyResult simplify(TriMesh& mesh, const SimplifyParams& params) {
  if (mesh.n_faces() == 0) throw InvalidInput("the mesh has no faces to simplify");
  SimplifyResult result;
  result.faces_before = mesh.n_faces();
  result.target_faces = target_of(mesh, params);
  mesh.request_face_normals();
  mesh.update_face_normals();
  const auto start = std::chrono::steady_clock::now();
  if (result.target_faces < result.faces_before) decimate_quadric(mesh, result.target_faces);
  mesh.garbage_collection();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.faces_after = mesh.n_faces();
  const double slack = 0.01 * static_cast<double>(result.target_faces);
  result.reached_target =
      std::abs(static_cast<double>(result.faces_after) - static_cast<double>(result.target_faces)) <= std::max(slack, 1.0);
  return result;
}

}  // namespace meshprep
