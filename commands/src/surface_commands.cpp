#include "meshprep/commands/surface_commands.h"

#include "stage_errors.h"

#include "meshprep/fem/readiness.h"
#include "meshprep/preprocess/compose/adaptive_reconstruction.h"
#include "meshprep/preprocess/compose/repair_solid.h"
#include "meshprep/quality/json_values.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/statistics.h"
#include "meshprep/quality/triangle_metrics.h"
#include "meshprep/report/report_writers.h"

namespace meshprep {

SmoothOutcome smooth_command(LoadedMesh input, const SmoothCommand& command, const CommandNames& names,
                              const CommandHooks& hooks) {
  require_all_faces(input, "smoothing");
  SmoothParams params = command.params;
  params.progress = hooks.until_deadline().progress;
  SmoothOutcome outcome;
  const SmoothResult& result = outcome.result = run_stage_on(names.input, [&] { return smooth(input.mesh, params); });
  add_taken_back_notes(result.taken_back, outcome.messages);
  outcome.surface = soup_from_mesh(input.mesh);

  QualityReport& quality = outcome.quality = analyze_quality(outcome.surface, command.quality, &input.soup);
  quality.path = names.output;
  quality.reference->path = names.input;
  const std::size_t input_intersections =
      result.input_self_intersections ? *result.input_self_intersections : find_self_intersections(input.soup).count;
  refuse_new_intersections(quality, input_intersections, names, "smoothed", "Use fewer --iterations", outcome.messages);

  std::vector<double> input_radius_ratio;
  for (const TriangleShape& shape : triangle_shapes(input.soup))
    if (!shape.degenerate) input_radius_ratio.push_back(shape.radius_ratio);
  nlohmann::ordered_json& json = outcome.report;
  json.update(to_json(result, params));
  json["input_radius_ratio"] = json_distribution(summarize(input_radius_ratio));
  json["input_self_intersections"] = input_intersections;
  json["quality"] = to_json(quality);
  if (params.preserve_volume && !result.volume_before)
    outcome.messages.push_back("warning: --preserve-volume ignored: the surface is not closed");
  return outcome;
}

EnhanceOutcome enhance_command(LoadedMesh input, const TriangleSoup* reference, const std::string& reference_name,
                               const EnhanceCommand& command, const CommandNames& names, const CommandHooks& hooks) {
  require_all_faces(input, "enhancement");
  if (reference && reference->triangles.empty()) throw InvalidInput(reference_name + ": the reference has no faces");
  EnhanceParams params = command.params;
  // Anytime: at the deadline the enhancement ends with its best rounds, written and judged.
  params.progress = hooks.progress;
  params.deadline = hooks.deadline;
  EnhanceOutcome outcome;
  const EnhanceResult& result = outcome.result =
      run_stage_on(names.input, [&] { return enhance(input.mesh, reference, params); });
  add_taken_back_notes(result.taken_back, outcome.messages);
  outcome.surface = soup_from_mesh(input.mesh);

  QualityReport& quality = outcome.quality =
      analyze_quality(outcome.surface, command.quality, reference ? reference : &input.soup);
  quality.path = names.output;
  quality.reference->path = reference ? reference_name : names.input;
  refuse_new_intersections(quality, result.input_self_intersections, names, "enhanced",
                           "Use --no-flips or a smaller --max-deviation", outcome.messages);
  nlohmann::ordered_json& json = outcome.report;
  json["reference"] = reference ? nlohmann::ordered_json(reference_name) : nlohmann::ordered_json(nullptr);
  json["faces_before"] = input.soup.triangles.size();
  json["faces_after"] = outcome.surface.triangles.size();
  json.update(to_json(result, params));
  json["quality"] = to_json(quality);
  return outcome;
}

std::string repair_summary(const RepairResult& r) {
  return "welded " + std::to_string(r.welded_vertices) + " vertices, removed " + std::to_string(r.degenerate_faces) +
         " degenerate and " + std::to_string(r.duplicate_faces) + " duplicate faces, split " +
         std::to_string(r.t_junction_splits) + " faces at T-junctions, split " +
         std::to_string(r.split_edges) + " non-manifold edges and " + std::to_string(r.split_vertices) +
         " vertices, dropped " + std::to_string(r.dropped_lone_faces) + " lone faces, flipped " +
         std::to_string(r.flipped_faces) + " faces, turned " +
         std::to_string(r.inverted_components) + " components outward, filled " + std::to_string(r.filled_holes) +
         " holes (" + std::to_string(r.open_holes) + " left open), cut " + std::to_string(r.cut_faces) + " faces along " +
         std::to_string(r.intersecting_pairs) + " intersecting pairs and removed " + std::to_string(r.removed_faces) +
         " pieces inside, dropped " + std::to_string(r.nested_components) + " nested parts (" +
         std::to_string(r.cavities) + " kept as cavities), moved apart " + std::to_string(r.separated_pinches) +
         " copies of points where parts touch" + envelope_summary(r);
}

RepairOutcome repair_command(TriangleSoup input, const RepairParams& params, const CommandNames& names,
                             const CommandHooks& hooks) {
  if (input.triangles.empty()) throw InvalidInput(names.input + ": no faces to repair");
  RepairOutcome outcome;
  RepairParams stoppable = params;
  stoppable.cancelled = hooks.until_deadline().cancelled;
  const RepairResult& result = outcome.result = [&] {
    try {
      return repair_solid(input, stoppable);
    } catch (const InvalidInput& e) {
      throw InvalidInput(names.input + ": " + e.what());
    }
  }();
  const Readiness readiness = check_fem_readiness(input, result.free_of_self_intersections);
  if (!readiness.ready()) {
    std::string left;
    for (const ReadinessProblem& p : readiness.problems) left += (left.empty() ? "" : "; ") + p.what;
    throw SolverError(names.input + ": " + repair_summary(result) + ", but what is left is not mended yet: " + left +
                      "; nothing written");
  }
  nlohmann::ordered_json& json = outcome.report;
  json["faces"] = input.triangles.size();
  json["vertices"] = input.points.size();
  json.update(to_json(result));
  json["readiness"] = to_json(readiness);
  outcome.surface = std::move(input);
  return outcome;
}

ReconstructOutcome reconstruct_command(const std::vector<Vec3>& points, const ReconstructCommand& command,
                                       const CommandNames& names, const CommandHooks& hooks) {
  const AdaptiveReconstructParams adaptive{command.params, hooks.until_deadline().progress};
  ReconstructOutcome outcome;
  ReconstructResult& result = outcome.result = run_stage_on(names.input, [&] {
    return command.adaptive ? reconstruct_adaptive(points, adaptive) : reconstruct_surface(points, command.params);
  });
  add_taken_back_notes(result.taken_back, outcome.messages);
  if (result.mesh.triangles.empty())
    throw SolverError(names.input + ": every triangle is farther than --max-gap " + std::to_string(result.max_gap) +
                      " from the samples; nothing written");
  nlohmann::ordered_json& json = outcome.report;
  json["points"] = points.size();
  const nlohmann::ordered_json record = to_json(result, command.params);
  for (const auto& [key, value] : record.items()) {
    json[key] = value;
    if (key == "grid") json["adaptive"] = command.adaptive;  // which of the two functions ran
  }
  outcome.surface = std::move(result.mesh);
  return outcome;
}

}  // namespace meshprep
