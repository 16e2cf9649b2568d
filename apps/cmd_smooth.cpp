// meshprep smooth IN -o OUT [--method rbf|taubin|laplace] [--neighbors N] [--iterations N]
//   [--smoothing L|inf] [--relaxation F] [--feature-angle DEG] [--preserve-volume] [--threads N]
//   [--json FILE|-]
#include "cli_common.h"
#include "cli_parameters.h"
#include "interrupt.h"
#include "progress_bar.h"

#include "meshprep/commands/surface_commands.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/preprocess/smooth/smooth.h"
#include "meshprep/preprocess/smooth/smooth_parameters.h"

#include <iostream>
#include <memory>

namespace meshprep::cli {
namespace {

struct SmoothOptions {
  std::string input, output, json;
  SmoothCommand command;
  std::size_t threads = 0;
};

int run_smooth(const SmoothOptions& o) {
  const ThreadLimit parallelism(o.threads);
  check_output_files({o.input}, {o.output, o.json});
  ProgressBar bar("smooth");
  const SmoothOutcome outcome =
      smooth_command(load_mesh(o.input), o.command, {o.input, o.output}, terminal_hooks([&bar](double f) { bar.update(f); }));
  bar.finish();
  write_soup(outcome.surface, o.output);
  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["output"] = o.output;
  json.update(outcome.report);
  if (!o.json.empty()) emit_json(json, o.json);
  const SmoothResult& result = outcome.result;
  if (o.json != "-") {
    std::cout << o.input << " -> " << o.output << ": " << choice_name(smooth_methods(), o.command.params.method) << ", "
              << result.iterations << " iteration(s) in " << result.seconds << " s; moved at most "
              << result.max_displacement << ", Hausdorff to the input " << outcome.quality.reference->hausdorff_relative
              << " of the diagonal";
    if (result.volume_before) std::cout << ", volume change " << 100 * (*result.volume_after / *result.volume_before - 1) << " %";
    std::cout << '\n';
  }
  print_messages(outcome.messages);
  return kSuccess;
}

}  // namespace

Action add_smooth_command(CLI::App& app) {
  auto o = std::make_shared<SmoothOptions>();
  CLI::App* cmd = app.add_subcommand("smooth", "Denoise a surface mesh, keeping its sharp features (RBF smoothing)");
  cmd->add_option("input", o->input, "Surface mesh (manifold; closed or with boundaries)")->required();
  cmd->add_option("-o,--output", o->output, "Smoothed surface (.off .obj .ply .stl)")->required();
  const SmoothParameters& p = smooth_parameters();
  add_choice(*cmd, p.method, o->command.params.method, smooth_methods());
  add_parameter(*cmd, p.iterations, o->command.params.iterations);
  add_parameter(*cmd, p.neighbors, o->command.params.neighbors);
  add_parameter(*cmd, p.smoothing, o->command.params.smoothing);
  add_parameter(*cmd, p.relaxation, o->command.params.relaxation);
  add_parameter(*cmd, p.feature_angle_deg, o->command.params.feature_angle_deg);
  add_parameter(*cmd, p.adaptive, o->command.params.adaptive);
  add_parameter(*cmd, p.preserve_volume, o->command.params.preserve_volume);
  add_samples_option(*cmd, o->command.quality.distance_samples);
  add_threads_option(*cmd, o->threads);
  cmd->add_option("--json", o->json, "Write the results and the quality of the output (against the input) as JSON");
  return [o] { return run_smooth(*o); };
}

}  // namespace meshprep::cli
