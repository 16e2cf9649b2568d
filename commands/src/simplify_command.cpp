#include "meshprep/commands/simplify_command.h"

#include "stage_errors.h"

#include "meshprep/preprocess/compose/simplify_and_enhance.h"
#include "meshprep/preprocess/simplify/simplify_parameters.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/topology.h"
#include "meshprep/report/report_writers.h"

#include <tbb/parallel_invoke.h>

namespace meshprep {
namespace {

// Topology and self-intersections are the contract of a simplifier: report them for the input too.
nlohmann::ordered_json input_topology(const TriangleSoup& soup) {
  const Topology topology = analyze_topology(soup);
  nlohmann::ordered_json json;
  json["closed"] = topology.closed;
  json["manifold"] = topology.manifold;
  json["genus"] = topology.genus ? nlohmann::ordered_json(*topology.genus) : nlohmann::ordered_json(nullptr);
  return json;
}

}  // namespace

SimplifyOutcome simplify_command(LoadedMesh input, const SimplifyCommand& command, const CommandNames& names,
                                const CommandHooks& hooks) {
  require_all_faces(input, "simplification");
  SimplifyParams params = command.params;
  params.progress = hooks.until_deadline().progress;
  SimplifyAndEnhanceResult enhanced;  // enhance: the Fig. 6 combination's figures
  SimplifyOutcome outcome;
  const SimplifyResult& result = outcome.result = run_stage_on(names.input, [&] {
    if (!command.enhance) return simplify(input.mesh, params);
    SimplifyAndEnhanceParams combined;
    combined.simplify = params;
    combined.progress = params.progress;
    enhanced = simplify_and_enhance(input.mesh, combined);
    return enhanced.simplify;
  });
  add_taken_back_notes(result.taken_back, outcome.messages);
  outcome.surface = soup_from_mesh(input.mesh);
  input.mesh.clear();  // (its arrays still had the input's size: 100 bytes a face)

  // The output's report and the input's topology are independent: measured side by side. The
  // input's self-intersections come after: their search is parallel itself, and its hierarchy
  // over the input would otherwise live beside the one the distance builds over it.
  nlohmann::ordered_json input_facts;
  tbb::parallel_invoke([&] { outcome.quality = analyze_quality(outcome.surface, command.quality, &input.soup); },
                       [&] { input_facts = input_topology(input.soup); });
  input_facts["self_intersections"] = find_self_intersections(input.soup).count;
  QualityReport& quality = outcome.quality;
  quality.path = names.output;
  quality.reference->path = names.input;
  // The guards have kept every output measured free of new self-intersections, but they do not
  // test for them: the report does, and a surface that intersects itself is not handed on.
  refuse_new_intersections(quality, input_facts["self_intersections"].get<std::size_t>(), names, "simplified",
                           "Keep more faces (--ratio) or raise --min-angle", outcome.messages);
  nlohmann::ordered_json& json = outcome.report;
  json["cost"] = choice_name(collapse_costs(), params.cost);
  json["min_angle_deg"] = params.min_angle_deg;
  json["max_error"] = params.max_error;
  json.update(command.enhance ? to_json(enhanced) : to_json(result));
  json["input_topology"] = input_facts;
  json["quality"] = to_json(quality);
  if (!result.reached_target)
    outcome.messages.push_back(
        "warning: stopped at " + std::to_string(result.faces_after) + " faces, target " +
        std::to_string(result.target_faces) + " (no further collapse passes the guards" +
        (params.max_error > 0 ? " and --max-error" : "") +
        (result.intersection_retries > 0 ? "; the error was bounded where the surface would intersect itself" : "") + ")");
  return outcome;
}

}  // namespace meshprep
