// meshprep enhance IN -o OUT [--reference ORIGINAL] [--iterations K] [--max-deviation E]
//   [--target-min-angle DEG] [--feature-angle DEG] [--flips | --no-flips] [--enhance-time-limit S]
//   [--size H] [--size-min H] [--size-max H] [--grading G] [--curvature-points N] [--thickness-layers K] [--threads N]
//   [--json FILE|-]
#include "cli_common.h"
#include "cli_parameters.h"
#include "interrupt.h"
#include "progress_bar.h"

#include "meshprep/commands/surface_commands.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/preprocess/enhance/enhance.h"
#include "meshprep/preprocess/enhance/enhance_parameters.h"

#include <iostream>
#include <memory>
#include <optional>

namespace meshprep::cli {
namespace {

struct EnhanceOptions {
  std::string input, output, reference, json;
  EnhanceCommand command;
  SizeFlags size;
  std::size_t threads = 0;
};

int run_enhance(const EnhanceOptions& o) {
  const ThreadLimit parallelism(o.threads);
  check_output_files({o.input, o.reference}, {o.output, o.json});
  LoadedMesh input = load_mesh(o.input);
  require_all_faces(input, "enhancement");
  const std::optional<TriangleSoup> reference = o.reference.empty() ? std::nullopt : std::optional(read_soup(o.reference));
  ProgressBar bar("enhance");
  EnhanceCommand command = o.command;
  command.params.size = o.size.applied_to(command.params.size);
  const EnhanceOutcome outcome =
      enhance_command(std::move(input), reference ? &*reference : nullptr, o.reference, command, {o.input, o.output},
                      terminal_hooks([&bar](double f) { bar.update(f); }));
  bar.finish();
  write_soup(outcome.surface, o.output);
  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["output"] = o.output;
  json.update(outcome.report);
  if (!o.json.empty()) emit_json(json, o.json);
  const EnhanceResult& result = outcome.result;
  if (o.json != "-")
    std::cout << o.input << " -> " << o.output << ": " << result.kept_round << " round(s), " << result.flips
              << " flips and " << result.cap_flips << " of caps in " << result.seconds << " s; faces under "
              << o.command.params.target_min_angle_deg << " deg " << 100 * result.before.under_target_fraction << " % -> "
              << 100 * result.after.under_target_fraction << " %, smallest angle " << result.before.min_angle_deg
              << " -> " << result.after.min_angle_deg << " deg, Hausdorff to the " << (reference ? "reference " : "input ")
              << outcome.quality.reference->hausdorff_relative << " of the diagonal"
              << (result.stopped_by_time_limit ? " (stopped at the time limit: the best rounds so far)" : "") << "\n";
  print_messages(outcome.messages);
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
  add_parameter(*cmd, p.iterations, o->command.params.iterations);
  add_auto_parameter(*cmd, p.max_deviation, o->command.params.max_deviation);
  add_parameter(*cmd, p.target_min_angle_deg, o->command.params.target_min_angle_deg);
  add_parameter(*cmd, p.feature_angle_deg, o->command.params.feature_angle_deg);
  add_parameter(*cmd, p.flips, o->command.params.flips);
  add_choice(*cmd, p.remesh, o->command.params.remesh, enhance_remesh_modes());
  add_parameter(*cmd, p.max_faces, o->command.params.max_faces);
  add_parameter(*cmd, p.time_limit_seconds, o->command.params.time_limit_seconds);
  add_size_options(*cmd, o->size);
  add_samples_option(*cmd, o->command.quality.distance_samples);
  add_threads_option(*cmd, o->threads);
  cmd->add_option("--json", o->json, "Write the results and the quality of the output (against the reference) as JSON");
  return [o] { return run_enhance(*o); };
}

}  // namespace meshprep::cli
