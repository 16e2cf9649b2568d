// meshprep enhance IN -o OUT [--reference ORIGINAL] [--iterations K] [--max-deviation E]
//   [--target-min-angle DEG] [--feature-angle DEG] [--flips | --no-flips] [--threads N] [--json FILE|-]
#include "cli_common.h"
#include "cli_parameters.h"
#include "interrupt.h"
#include "progress_bar.h"
#include "stage_failure.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/preprocess/enhance/enhance.h"
#include "meshprep/preprocess/enhance/enhance_parameters.h"
#include "meshprep/quality/report.h"
#include "meshprep/report/report_writers.h"

#include <iostream>
#include <memory>

namespace meshprep::cli {
namespace {

struct EnhanceOptions {
  std::string input, output, reference, json;
  EnhanceParams params;
  std::size_t samples = QualityParams().distance_samples;
  std::size_t threads = 0;
};

int run_enhance(EnhanceOptions o) {
  const ThreadLimit parallelism(o.threads);
  check_output_files({o.input, o.reference}, {o.output, o.json});
  LoadedMesh loaded = load_mesh(o.input);
  require_all_faces(loaded, "enhancement");
  std::unique_ptr<TriangleSoup> reference;
  if (!o.reference.empty()) {
    reference = std::make_unique<TriangleSoup>(read_soup(o.reference));
    if (reference->triangles.empty()) throw InvalidInput(o.reference + ": the reference has no faces");
  }
  ProgressBar bar("enhance");
  o.params.progress = stoppable([&bar](double fraction) { bar.update(fraction); });
  const EnhanceResult result = run_stage_on(o.input, [&] { return enhance(loaded.mesh, reference.get(), o.params); });
  note_taken_back(result.taken_back);
  bar.finish();
  const TriangleSoup output = soup_from_mesh(loaded.mesh);

  const TriangleSoup& against = reference ? *reference : loaded.soup;
  QualityParams quality_params;
  quality_params.distance_samples = o.samples;
  QualityReport quality = analyze_quality(output, quality_params, &against);
  quality.path = o.output;
  quality.reference->path = reference ? o.reference : o.input;
  refuse_new_intersections(quality, result.input_self_intersections, o.input, "enhanced",
                           "Use --no-flips or a smaller --max-deviation");
  write_soup(output, o.output);

  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["output"] = o.output;
  json["reference"] = reference ? nlohmann::ordered_json(o.reference) : nlohmann::ordered_json(nullptr);
  json["faces_before"] = loaded.soup.triangles.size();
  json["faces_after"] = output.triangles.size();
  json.update(to_json(result, o.params));
  json["quality"] = to_json(quality);
  if (!o.json.empty()) emit_json(json, o.json);
  if (o.json != "-")
    std::cout << o.input << " -> " << o.output << ": " << result.kept_round << " round(s), " << result.flips
              << " flips and " << result.cap_flips << " of caps in " << result.seconds << " s; faces under "
              << o.params.target_min_angle_deg << " deg "
              << 100 * result.before.under_target_fraction << " % -> " << 100 * result.after.under_target_fraction
              << " %, smallest angle " << result.before.min_angle_deg << " -> " << result.after.min_angle_deg
              << " deg, Hausdorff to the " << (reference ? "reference " : "input ")
              << quality.reference->hausdorff_relative << " of the diagonal\n";
  return kSuccess;
}

}  // namespace

Action add_enhance_command(CLI::App& app) {
  auto o = std::make_shared<EnhanceOptions>();
  CLI::App* cmd = app.add_subcommand(
      "enhance", "Improve the triangles' shapes without leaving the surface (statistical enhancement with Ceres)");
  cmd->add_option("input", o->input, "Surface mesh (manifold; closed or with boundaries)")->required();
  cmd->add_option("-o,--output", o->output, "Enhanced surface (.off .obj .ply .stl)")->required();
  cmd->add_option("--reference", o->reference,
                  "The original surface to stay on (e.g. the mesh before simplification); default: the input");
  const EnhanceParameters& p = enhance_parameters();
  add_parameter(*cmd, p.iterations, o->params.iterations);
  add_auto_parameter(*cmd, p.max_deviation, o->params.max_deviation);
  add_parameter(*cmd, p.target_min_angle_deg, o->params.target_min_angle_deg);
  add_parameter(*cmd, p.feature_angle_deg, o->params.feature_angle_deg);
  add_parameter(*cmd, p.flips, o->params.flips);
  add_choice(*cmd, p.remesh, o->params.remesh, enhance_remesh_modes());
  add_parameter(*cmd, p.max_faces, o->params.max_faces);
  add_samples_option(*cmd, o->samples);
  add_threads_option(*cmd, o->threads);
  cmd->add_option("--json", o->json, "Write the results and the quality of the output (against the reference) as JSON");
  return [o] { return run_enhance(*o); };
}

}  // namespace meshprep::cli
