#include "meshprep/preprocess/compose/repair_solid.h"

#include "meshprep/core/errors.h"
#include "meshprep/preprocess/enhance/enhance.h"
#include "meshprep/preprocess/simplify/simplify.h"

#include <algorithm>
#include <chrono>

namespace meshprep {

namespace {

// A collapse may move the surface by this share of the fidelity bound: the grid's surface keeps
// the rest for the stages after.
constexpr double kReductionShare = 0.25;

}  // namespace

RepairResult repair_solid(TriangleSoup& surface, RepairParams params) {
  if (!(params.fidelity_bound > 0)) params.fidelity_bound = EnhanceParams::kLargestAutoDeviation;
  const std::size_t input_faces = surface.triangles.size();
  RepairResult result = repair(surface, params);
  if (!result.envelope) return result;
  const auto start = std::chrono::steady_clock::now();
  const auto poll = [&params](double) {
    if (params.cancelled && params.cancelled()) throw Cancelled("repair stopped");
  };
  poll(0);
  TriMesh mesh = mesh_from_soup(surface);
  SimplifyParams reduction;
  reduction.progress = poll;  // the simplification reports as it goes: the user's stop and the deadline
  reduction.target_faces = std::min(input_faces, mesh.n_faces());
  reduction.max_error = kReductionShare * params.fidelity_bound;
  simplify(mesh, reduction);
  surface = soup_from_mesh(mesh);
  result.envelope->reduced_faces = surface.triangles.size();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.envelope->seconds += seconds;
  result.seconds += seconds;
  return result;
}

}  // namespace meshprep
