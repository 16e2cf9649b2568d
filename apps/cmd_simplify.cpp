// meshprep simplify IN -o OUT (--ratio R | --faces N) [--cost bending|distance|quadric]
//   [--max-error E] [--min-angle DEG] [--no-polish] [--enhance] [--threads N] [--json FILE|-]
#include "cli_common.h"
#include "cli_parameters.h"
#include "interrupt.h"
#include "progress_bar.h"

#include "meshprep/commands/simplify_command.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/preprocess/simplify/simplify_parameters.h"

#include <iostream>
#include <memory>

namespace meshprep::cli {
namespace {

struct SimplifyOptions {
  std::string input, output, json;
  SimplifyCommand command;
  double ratio = 0;  ///< 0: --faces
  std::size_t threads = 0;
};

int run_simplify(const SimplifyOptions& o) {
  const ThreadLimit parallelism(o.threads);
  check_output_files({o.input}, {o.output, o.json});
  if ((o.ratio > 0) == (o.command.params.target_faces > 0)) throw InvalidInput("give exactly one of --ratio and --faces");
  SimplifyCommand command = o.command;
  command.params.keep_ratio = o.ratio > 0 ? o.ratio : 1.0;
  ProgressBar bar("simplify");
  const SimplifyOutcome outcome =
      simplify_command(load_mesh(o.input), command, {o.input, o.output}, terminal_hooks([&bar](double f) { bar.update(f); }));
  bar.finish();
  write_soup(outcome.surface, o.output);
  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["output"] = o.output;
  json.update(outcome.report);
  if (!o.json.empty()) emit_json(json, o.json);
  const SimplifyResult& result = outcome.result;
  const QualityReport& quality = outcome.quality;
  if (o.json != "-")
    std::cout << o.input << " -> " << o.output << ": " << result.faces_before << " -> " << result.faces_after
              << " faces in " << result.seconds << " s; Hausdorff " << quality.reference->hausdorff_relative
              << " of the diagonal, min angle < 20 deg on " << 100 * quality.faces_min_angle_below_20
              << " % of faces, radius ratio p95 " << quality.radius_ratio.p95 << '\n';
  print_messages(outcome.messages);
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
  cmd->add_option(p.target_faces.flag, o->command.params.target_faces, "Target number of faces")
      ->check(positive())
      ->excludes(ratio);
  add_choice(*cmd, p.cost, o->command.params.cost, collapse_costs());
  add_parameter(*cmd, p.max_error, o->command.params.max_error);
  add_parameter(*cmd, p.min_angle_deg, o->command.params.min_angle_deg);
  cmd->add_flag("--enhance", o->command.enhance,
                "Reduce in three stages, each followed by the statistical enhancement against the input (meshprep "
                "enhance; the paper's Figure 6 combination)");
  add_parameter(*cmd, p.polish, o->command.params.polish);
  add_samples_option(*cmd, o->command.quality.distance_samples);
  add_threads_option(*cmd, o->threads);
  cmd->add_option("--json", o->json, "Write the results and the quality of the output (against the input) as JSON");
  return [o] { return run_simplify(*o); };
}

}  // namespace meshprep::cli
