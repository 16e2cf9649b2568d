#include "meshprep/preprocess/compose/simplify_and_enhance.h"

#include "meshprep/core/finite_points.h"
#include "meshprep/core/origin_shift.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>

namespace meshprep {
namespace {

constexpr int kEnhanceStages = 3;

}  // namespace

SimplifyAndEnhanceResult simplify_and_enhance(TriMesh& mesh, const SimplifyAndEnhanceParams& params) {
  SimplifyAndEnhanceResult result;
  SimplifyParams stage = params.simplify;
  stage.progress = params.progress;
  if (stage.cost == CollapseCost::Quadric) {
    result.simplify = simplify(mesh, stage);
    return result;
  }
  // Each step's simplify() reports its end with 1; the whole goes on to s / 3 instead.
  if (params.progress)
    stage.progress = [&params](double fraction) {
      if (fraction < 1) params.progress(fraction);
    };
  const std::size_t target = simplify_target(mesh, stage);  // the parameters checked before any work
  // The whole runs next to the origin, and the enhancements' reference with it; the steps' own
  // shifts are then zero (origin_shift.h: a bounding box around the origin is not moved).
  const ShiftedToOrigin near_origin(mesh);
  const auto start = std::chrono::steady_clock::now();
  const TriangleSoup original = soup_from_mesh(mesh);
  SimplifyResult& total = result.simplify;
  total.faces_before = mesh.n_faces();
  total.target_faces = target;
  EnhanceParams enhancement = params.enhance;
  enhancement.max_face_change = 0.01 / kEnhanceStages;
  const double step = static_cast<double>(total.target_faces) / static_cast<double>(total.faces_before);
  for (int s = 1; s <= kEnhanceStages; ++s) {
    stage.target_faces = s == kEnhanceStages ? total.target_faces
                                             : static_cast<std::size_t>(std::llround(static_cast<double>(total.faces_before) *
                                                                                     std::pow(step, double(s) / kEnhanceStages)));
    const SimplifyResult r = simplify(mesh, stage);
    total.collapses += r.collapses;
    total.rejected_topology += r.rejected_topology;
    total.rejected_shape += r.rejected_shape;
    total.rejected_error += r.rejected_error;
    total.energy_evaluations += r.energy_evaluations;
    total.polish_flips += r.polish_flips;
    total.polish_moves += r.polish_moves;
    total.fit_moves += r.fit_moves;
    total.intersection_retries += r.intersection_retries;
    total.taken_back.insert(total.taken_back.end(), r.taken_back.begin(), r.taken_back.end());
    const EnhanceResult e = enhance(mesh, &original, enhancement);
    total.taken_back.insert(total.taken_back.end(), e.taken_back.begin(), e.taken_back.end());
    ++result.stages;
    result.rounds += e.kept_round;
    result.flips += e.flips;
    result.removed_vertices += e.removed_vertices;
    result.split_edges += e.split_edges;
    if (params.progress) params.progress(static_cast<double>(s) / kEnhanceStages);
  }
  total.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  total.faces_after = mesh.n_faces();
  require_finite_points(mesh, "simplify");
  if (params.progress) params.progress(1.0);
  total.reached_target = reaches_target(total.faces_after, total.target_faces);
  return result;
}

nlohmann::ordered_json to_json(const SimplifyAndEnhanceResult& result) {
  nlohmann::ordered_json json = to_json(result.simplify);
  json["enhance"] = {{"stages", result.stages},
                     {"rounds", result.rounds},
                     {"flips", result.flips},
                     {"removed_vertices", result.removed_vertices},
                     {"split_edges", result.split_edges}};
  return json;
}

}  // namespace meshprep
