// meshprep smooth IN -o OUT [--method rbf|taubin|laplace] [--neighbors N] [--iterations N]
//   [--smoothing L|inf] [--relaxation F] [--feature-angle DEG] [--preserve-volume] [--threads N]
//   [--json FILE|-]
#include "cli_common.h"
#include "cli_parameters.h"
#include "interrupt.h"
#include "progress_bar.h"
#include "stage_failure.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/preprocess/smooth/smooth.h"
#include "meshprep/preprocess/smooth/smooth_parameters.h"
#include "meshprep/quality/json_values.h"
#include "meshprep/quality/report.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/triangle_metrics.h"
#include "meshprep/report/report_writers.h"

#include <iostream>
#include <memory>

namespace meshprep::cli {
namespace {

struct SmoothOptions {
  std::string input, output, json;
  SmoothParams params;
  std::size_t samples = QualityParams().distance_samples;
  std::size_t threads = 0;
};

int run_smooth(SmoothOptions o) {
  const ThreadLimit parallelism(o.threads);
  check_output_files({o.input}, {o.output, o.json});
  LoadedMesh loaded = load_mesh(o.input);
  require_all_faces(loaded, "smoothing");
  ProgressBar bar("smooth");
  o.params.progress = stoppable([&bar](double fraction) { bar.update(fraction); });
  const SmoothResult result = run_stage_on(o.input, [&] { return smooth(loaded.mesh, o.params); });
  note_taken_back(result.taken_back);
  bar.finish();
  const TriangleSoup output = soup_from_mesh(loaded.mesh);

  QualityParams quality_params;
  quality_params.distance_samples = o.samples;
  QualityReport quality = analyze_quality(output, quality_params, &loaded.soup);
  quality.path = o.output;
  quality.reference->path = o.input;
  const std::size_t input_intersections =
      result.input_self_intersections ? *result.input_self_intersections : find_self_intersections(loaded.soup).count;
  refuse_new_intersections(quality, input_intersections, o.input, "smoothed", "Use fewer --iterations");
  write_soup(output, o.output);

  std::vector<double> input_radius_ratio;
  for (const TriangleShape& shape : triangle_shapes(loaded.soup))
    if (!shape.degenerate) input_radius_ratio.push_back(shape.radius_ratio);
  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["output"] = o.output;
  json.update(to_json(result, o.params));
  json["input_radius_ratio"] = json_distribution(summarize(input_radius_ratio));
  json["input_self_intersections"] = input_intersections;
  json["quality"] = to_json(quality);
  if (!o.json.empty()) emit_json(json, o.json);
  if (o.json != "-") {
    std::cout << o.input << " -> " << o.output << ": " << choice_name(smooth_methods(), o.params.method) << ", "
              << result.iterations << " iteration(s) in "
              << result.seconds << " s; moved at most " << result.max_displacement << ", Hausdorff to the input "
              << quality.reference->hausdorff_relative << " of the diagonal";
    if (result.volume_before) std::cout << ", volume change " << 100 * (*result.volume_after / *result.volume_before - 1) << " %";
    std::cout << '\n';
  }
  if (o.params.preserve_volume && !result.volume_before)
    std::cerr << "meshprep: warning: --preserve-volume ignored: the surface is not closed\n";
  return kSuccess;
}

}  // namespace

Action add_smooth_command(CLI::App& app) {
  auto o = std::make_shared<SmoothOptions>();
  CLI::App* cmd = app.add_subcommand("smooth", "Denoise a surface mesh, keeping its sharp features (RBF smoothing)");
  cmd->add_option("input", o->input, "Surface mesh (manifold; closed or with boundaries)")->required();
  cmd->add_option("-o,--output", o->output, "Smoothed surface (.off .obj .ply .stl)")->required();
  const SmoothParameters& p = smooth_parameters();
  add_choice(*cmd, p.method, o->params.method, smooth_methods());
  add_parameter(*cmd, p.iterations, o->params.iterations);
  add_parameter(*cmd, p.neighbors, o->params.neighbors);
  add_parameter(*cmd, p.smoothing, o->params.smoothing);
  add_parameter(*cmd, p.relaxation, o->params.relaxation);
  add_parameter(*cmd, p.feature_angle_deg, o->params.feature_angle_deg);
  add_parameter(*cmd, p.adaptive, o->params.adaptive);
  add_parameter(*cmd, p.preserve_volume, o->params.preserve_volume);
  add_samples_option(*cmd, o->samples);
  add_threads_option(*cmd, o->threads);
  cmd->add_option("--json", o->json, "Write the results and the quality of the output (against the input) as JSON");
  return [o] { return run_smooth(*o); };
}

}  // namespace meshprep::cli
