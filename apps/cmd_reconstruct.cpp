// meshprep reconstruct POINTS.xyz -o MESH [--resolution NX NY | --vertices N | --spacing H]
//   [--leaf-size K] [--neighbors N] [--variation-threshold T|pNN] [--variation-growth G]
//   [--adaptive] [--max-gap G] [--threads N] [--json FILE|-]
#include "cli_common.h"
#include "cli_parameters.h"
#include "interrupt.h"
#include "progress_bar.h"

#include "meshprep/commands/surface_commands.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/preprocess/reconstruct/reconstruct.h"
#include "meshprep/preprocess/reconstruct/reconstruct_parameters.h"
#include "meshprep/preprocess/reconstruct/variation_rule.h"

#include <iostream>
#include <memory>
#include <vector>

namespace meshprep::cli {
namespace {

struct ReconstructOptions {
  std::string input, output, json;
  ReconstructParams params;
  std::vector<std::size_t> resolution{params.columns, params.rows};
  bool adaptive = false;
  std::size_t threads = 0;
};

std::string check_variation_rule(const std::string& text) {
  PartitionOfUnityParams scratch;
  return apply_variation_rule(text, scratch) ? std::string() : variation_rule_error(text);
}

int run_reconstruct(const ReconstructOptions& o) {
  const ThreadLimit parallelism(o.threads);
  check_output_files({o.input}, {o.output, o.json});
  const PointSet input = read_points(o.input);
  ReconstructCommand command{o.params, o.adaptive};
  command.params.columns = o.resolution[0];
  command.params.rows = o.resolution[1];
  ProgressBar bar("reconstruct");
  const ReconstructOutcome outcome =
      reconstruct_command(input.points, command, {o.input, o.output}, terminal_hooks([&bar](double f) { bar.update(f); }));
  bar.finish();
  const ReconstructResult& result = outcome.result;
  WriteOptions write;
  write.vertex_scalars.push_back({"surface_variation", result.vertex_variation});  // PLY only
  write_soup(outcome.surface, o.output, write);

  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["output"] = o.output;
  json.update(outcome.report);
  if (!o.json.empty()) emit_json(json, o.json);
  if (o.json != "-") {
    std::cout << o.input << " -> " << o.output << ": " << input.points.size() << " points, "
              << outcome.surface.points.size() << " vertices, " << outcome.surface.triangles.size() << " faces ("
              << result.gap_triangles << " left out over gaps wider than " << result.max_gap;
    if (command.params.fill_holes) std::cout << "; " << result.filled_triangles << " kept over holes in the data, flagged";
    std::cout << ") in " << result.seconds << " s\n";
  }
  print_messages(outcome.messages);
  return kSuccess;
}

}  // namespace

Action add_reconstruct_command(CLI::App& app) {
  auto o = std::make_shared<ReconstructOptions>();
  CLI::App* cmd = app.add_subcommand(
      "reconstruct", "Scattered points (a height field over a disc-like domain) -> triangle mesh, by an RBF partition of unity");
  cmd->add_option("input", o->input, "Point set (.xyz)")->required();
  cmd->add_option("-o,--output", o->output, "Surface mesh (.off .obj .ply .stl; .ply also stores sigma per vertex)")->required();
  const ReconstructParameters& p = reconstruct_parameters();
  auto* resolution = cmd->add_option(p.resolution.flag, o->resolution, capitalised(p.resolution.help))
                         ->expected(2)
                         ->check(range_check(p.resolution.range))
                         ->capture_default_str();
  auto* spacing = add_parameter(*cmd, p.spacing, o->params.spacing)->excludes(resolution);
  add_parameter(*cmd, p.vertices, o->params.vertices)->excludes(resolution)->excludes(spacing);
  add_parameter(*cmd, p.leaf_size, o->params.fit.leaf_size);
  add_parameter(*cmd, p.neighbors, o->params.fit.neighbors);
  cmd->add_option_function<std::string>(
         p.variation_threshold.flag,
         [o](const std::string& text) { apply_variation_rule(text, o->params.fit); },  // checked below
         capitalised(p.variation_threshold.help))
      ->check(CLI::Validator(check_variation_rule, "T|pNN"))
      ->default_str(variation_rule_text(o->params.fit));
  add_parameter(*cmd, p.variation_growth, o->params.fit.variation_growth);
  add_parameter(*cmd, p.adaptive, o->adaptive);
  add_parameter(*cmd, p.max_gap, o->params.max_gap);
  add_parameter(*cmd, p.fill_holes, o->params.fill_holes);
  add_threads_option(*cmd, o->threads);
  cmd->add_option("--json", o->json, "Write the results as JSON (- for standard output)");
  return [o] { return run_reconstruct(*o); };
}

}  // namespace meshprep::cli
