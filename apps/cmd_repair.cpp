// meshprep repair IN -o OUT [--weld-tolerance R] [--max-hole R|auto] [--json FILE|-]: a dirty surface
// mended (preprocess/repair/repair.h), then checked as tetrahedralize checks it: written only if
// closed, manifold, oriented and free of self-intersections, else exit 1 naming what is left.
#include "cli_common.h"
#include "cli_parameters.h"

#include "meshprep/commands/surface_commands.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/fem/readiness.h"
#include "meshprep/preprocess/repair/repair.h"
#include "meshprep/preprocess/repair/repair_parameters.h"

#include <iostream>
#include <memory>
#include <string>

namespace meshprep::cli {
namespace {

struct RepairOptions {
  std::string input, output, json;
  RepairParams params;
};

int run_repair(const RepairOptions& o) {
  check_output_files({o.input}, {o.output, o.json});
  const RepairOutcome outcome = repair_command(read_soup(o.input), o.params, {o.input, o.output}, terminal_hooks());
  write_soup(outcome.surface, o.output);
  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["output"] = o.output;
  json.update(outcome.report);
  if (!o.json.empty()) emit_json(json, o.json);
  if (o.json != "-")
    std::cout << o.input << " -> " << o.output << ": " << repair_summary(outcome.result)
              << "; closed, manifold, oriented, no self-intersections (" << outcome.surface.triangles.size() << " faces)\n";
  return kSuccess;
}

}  // namespace

Action add_repair_command(CLI::App& app) {
  auto o = std::make_shared<RepairOptions>();
  CLI::App* cmd = app.add_subcommand(
      "repair",
      "Mend a dirty surface (weld split vertices, split faces at T-junctions, drop degenerate and duplicate "
      "faces, split non-manifold edges and vertices, drop lone faces (fins), orient consistently and outward, "
      "fill holes: all but an open sheet's outline, or those up to --max-hole; cut self-intersections and keep "
      "the union's boundary, or rebuild the solid on a grid where the cut leaves crossings); written only if it is then ready for tetrahedralize");
  cmd->add_option("input", o->input, "Surface mesh (.off .obj .ply .stl)")->required();
  cmd->add_option("-o,--output", o->output, "Repaired surface (.off .obj .ply .stl)")->required();
  add_parameter(*cmd, repair_parameters().weld_tolerance, o->params.weld_tolerance);
  add_auto_parameter(*cmd, repair_parameters().max_hole, o->params.max_hole);
  add_parameter(*cmd, repair_parameters().keep_cavities, o->params.keep_cavities);
  add_choice(*cmd, repair_parameters().route, o->params.route, repair_routes());
  add_parameter(*cmd, repair_parameters().envelope_cells, o->params.envelope_cells);
  add_parameter(*cmd, repair_parameters().time_limit_seconds, o->params.time_limit_seconds);
  cmd->add_option("--json", o->json, "Write the counts of each step and the readiness as JSON (- for standard output)");
  return [o] { return run_repair(*o); };
}

}  // namespace meshprep::cli
