// meshprep repair IN -o OUT [--weld-tolerance R] [--max-hole R|auto] [--json FILE|-]: a dirty surface
// mended (preprocess/repair/repair.h), then checked as tetrahedralize checks it: written only if
// closed, manifold, oriented and free of self-intersections, else exit 1 naming what is left.
#include "cli_common.h"
#include "cli_parameters.h"

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

// "welded 28 vertices, removed 0 degenerate and 1 duplicate faces, split 1 non-manifold edges and
// 2 vertices, flipped 2 faces, turned 0 components outward, filled 3 holes (2 left open)".
std::string done_line(const RepairResult& r) {
  return "welded " + std::to_string(r.welded_vertices) + " vertices, removed " + std::to_string(r.degenerate_faces) +
         " degenerate and " + std::to_string(r.duplicate_faces) + " duplicate faces, split " +
         std::to_string(r.split_edges) + " non-manifold edges and " + std::to_string(r.split_vertices) +
         " vertices, flipped " + std::to_string(r.flipped_faces) + " faces, turned " +
         std::to_string(r.inverted_components) + " components outward, filled " + std::to_string(r.filled_holes) +
         " holes (" + std::to_string(r.open_holes) + " left open), cut " + std::to_string(r.cut_faces) + " faces along " +
         std::to_string(r.intersecting_pairs) + " intersecting pairs and removed " + std::to_string(r.removed_faces) +
         " pieces inside, dropped " + std::to_string(r.nested_components) + " nested parts (" +
         std::to_string(r.cavities) + " kept as cavities), moved apart " + std::to_string(r.separated_pinches) +
         " copies of points where parts touch";
}

int run_repair(const RepairOptions& o) {
  check_output_files({o.input}, {o.output, o.json});
  TriangleSoup surface = read_soup(o.input);
  if (surface.triangles.empty()) throw InvalidInput(o.input + ": no faces to repair");
  const RepairResult result = [&] {
    try {
      return repair(surface, o.params);
    } catch (const InvalidInput& e) {
      throw InvalidInput(o.input + ": " + e.what());
    }
  }();
  const Readiness readiness = check_fem_readiness(surface, result.free_of_self_intersections);
  if (!readiness.ready()) {
    std::string left;
    for (const ReadinessProblem& p : readiness.problems) left += (left.empty() ? "" : "; ") + p.what;
    throw WorkFailed(o.input + ": " + done_line(result) + ", but what is left is not mended yet: " + left +
                     "; nothing written");
  }
  write_soup(surface, o.output);
  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["output"] = o.output;
  json["faces"] = surface.triangles.size();
  json["vertices"] = surface.points.size();
  json.update(to_json(result));
  json["readiness"] = to_json(readiness);
  if (!o.json.empty()) emit_json(json, o.json);
  if (o.json != "-")
    std::cout << o.input << " -> " << o.output << ": " << done_line(result)
              << "; closed, manifold, oriented, no self-intersections (" << surface.triangles.size() << " faces)\n";
  return kSuccess;
}

}  // namespace

Action add_repair_command(CLI::App& app) {
  auto o = std::make_shared<RepairOptions>();
  CLI::App* cmd = app.add_subcommand(
      "repair",
      "Mend a dirty surface (weld split vertices, drop degenerate and duplicate faces, split non-manifold edges "
      "and vertices, orient consistently and outward, fill holes: all but an open sheet's outline, or those up to "
      "--max-hole; cut self-intersections and keep the union's boundary); written only if it is then ready for "
      "tetrahedralize");
  cmd->add_option("input", o->input, "Surface mesh (.off .obj .ply .stl)")->required();
  cmd->add_option("-o,--output", o->output, "Repaired surface (.off .obj .ply .stl)")->required();
  add_parameter(*cmd, repair_parameters().weld_tolerance, o->params.weld_tolerance);
  add_auto_parameter(*cmd, repair_parameters().max_hole, o->params.max_hole);
  add_parameter(*cmd, repair_parameters().keep_cavities, o->params.keep_cavities);
  cmd->add_option("--json", o->json, "Write the counts of each step and the readiness as JSON (- for standard output)");
  return [o] { return run_repair(*o); };
}

}  // namespace meshprep::cli
