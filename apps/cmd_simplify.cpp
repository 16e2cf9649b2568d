// meshprep simplify IN -o OUT (--ratio R | --faces N) [--cost bending|distance|quadric]
//   [--max-error E] [--min-angle DEG] [--no-polish] [--enhance] [--threads N] [--json FILE|-]
#include "cli_common.h"
#include "cli_parameters.h"
#include "interrupt.h"
#include "progress_bar.h"
#include "stage_failure.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/preprocess/compose/simplify_and_enhance.h"
#include "meshprep/preprocess/simplify/simplify.h"
#include "meshprep/preprocess/simplify/simplify_parameters.h"
#include "meshprep/quality/report.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/topology.h"
#include "meshprep/report/report_writers.h"

#include <iostream>
#include <memory>

namespace meshprep::cli {
namespace {

struct SimplifyOptions {
  std::string input, output, json;
  SimplifyParams params;
  double ratio = 0;  ///< 0: --faces
  std::size_t samples = QualityParams().distance_samples;
  std::size_t threads = 0;
  bool enhance = false;
};

// Topology and self-intersections are the contract of a simplifier: report them for the input too.
nlohmann::ordered_json input_facts(const TriangleSoup& soup) {
  const Topology topology = analyze_topology(soup);
  nlohmann::ordered_json json;
  json["closed"] = topology.closed;
  json["manifold"] = topology.manifold;
  json["genus"] = topology.genus ? nlohmann::ordered_json(*topology.genus) : nlohmann::ordered_json(nullptr);
  json["self_intersections"] = find_self_intersections(soup).count;
  return json;
}

int run_simplify(const SimplifyOptions& o) {
  const ThreadLimit parallelism(o.threads);
  check_output_files({o.input}, {o.output, o.json});
  if ((o.ratio > 0) == (o.params.target_faces > 0)) throw InvalidInput("give exactly one of --ratio and --faces");
  LoadedMesh loaded = load_mesh(o.input);
  require_all_faces(loaded, "simplification");
  SimplifyParams params = o.params;
  params.keep_ratio = o.ratio > 0 ? o.ratio : 1.0;
  ProgressBar bar("simplify");
  params.progress = stoppable([&bar](double fraction) { bar.update(fraction); });
  SimplifyAndEnhanceResult enhanced;  // --enhance: the Fig. 6 combination's figures
  const SimplifyResult result = run_stage_on(o.input, [&] {
    if (!o.enhance) return simplify(loaded.mesh, params);
    SimplifyAndEnhanceParams combined;
    combined.simplify = params;
    combined.progress = params.progress;
    enhanced = simplify_and_enhance(loaded.mesh, combined);
    return enhanced.simplify;
  });
  bar.finish();
  note_taken_back(result.taken_back);
  const TriangleSoup output = soup_from_mesh(loaded.mesh);

  QualityParams quality_params;
  quality_params.distance_samples = o.samples;
  QualityReport quality = analyze_quality(output, quality_params, &loaded.soup);
  quality.path = o.output;
  quality.reference->path = o.input;
  const nlohmann::ordered_json input_topology = input_facts(loaded.soup);
  // The guards have kept every output measured free of new self-intersections, but they do not
  // test for them: the report does, and a surface that intersects itself is not written.
  const std::size_t input_intersections = input_topology["self_intersections"].get<std::size_t>();
  refuse_new_intersections(quality, input_intersections, o.input, "simplified",
                           "Keep more faces (--ratio) or raise --min-angle");
  write_soup(output, o.output);
  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["output"] = o.output;
  json["cost"] = choice_name(collapse_costs(), params.cost);
  json["min_angle_deg"] = params.min_angle_deg;
  json["max_error"] = params.max_error;
  json.update(o.enhance ? to_json(enhanced) : to_json(result));
  json["input_topology"] = input_topology;
  json["quality"] = to_json(quality);
  if (!o.json.empty()) emit_json(json, o.json);
  if (o.json != "-")
    std::cout << o.input << " -> " << o.output << ": " << result.faces_before << " -> " << result.faces_after
              << " faces in " << result.seconds << " s; Hausdorff " << quality.reference->hausdorff_relative
              << " of the diagonal, min angle < 20 deg on " << 100 * quality.faces_min_angle_below_20
              << " % of faces, radius ratio p95 " << quality.radius_ratio.p95 << '\n';
  if (!result.reached_target)
    std::cerr << "meshprep: warning: stopped at " << result.faces_after << " faces, target " << result.target_faces
              << " (no further collapse passes the guards" << (params.max_error > 0 ? " and --max-error" : "")
              << (result.intersection_retries > 0 ? "; the error was bounded where the surface would intersect itself" : "")
              << ")\n";
  return kSuccess;
}

}  // namespace

Action add_simplify_command(CLI::App& app) {
  auto o = std::make_shared<SimplifyOptions>();
  CLI::App* cmd = app.add_subcommand("simplify", "Reduce a surface mesh to a target size by edge collapse");
  cmd->add_option("input", o->input, "Surface mesh (manifold; closed or with boundaries)")->required();
  cmd->add_option("-o,--output", o->output, "Simplified surface (.off .obj .ply .stl)")->required();
  const SimplifyParameters& p = simplify_parameters();
  // --ratio has no default here: one of --ratio and --faces is required.
  auto* ratio = cmd->add_option(p.keep_ratio.flag, o->ratio, capitalised(p.keep_ratio.help))
                    ->check(range_check(p.keep_ratio.range));
  cmd->add_option(p.target_faces.flag, o->params.target_faces, "Target number of faces")
      ->check(positive())
      ->excludes(ratio);
  add_choice(*cmd, p.cost, o->params.cost, collapse_costs());
  add_parameter(*cmd, p.max_error, o->params.max_error);
  add_parameter(*cmd, p.min_angle_deg, o->params.min_angle_deg);
  cmd->add_flag("--enhance", o->enhance,
                "Reduce in three stages, each followed by the statistical enhancement against the input (meshprep "
                "enhance; the paper's Figure 6 combination)");
  add_parameter(*cmd, p.polish, o->params.polish);
  add_samples_option(*cmd, o->samples);
  add_threads_option(*cmd, o->threads);
  cmd->add_option("--json", o->json, "Write the results and the quality of the output (against the input) as JSON");
  return [o] { return run_simplify(*o); };
}

}  // namespace meshprep::cli
