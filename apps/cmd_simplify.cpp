// meshprep simplify IN -o OUT (--ratio R | --faces N) [--cost quadric] [--json FILE|-]
#include "cli_common.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/preprocess/simplify.h"
#include "meshprep/quality/report.h"
#include "meshprep/quality/report_writers.h"

#include <iostream>
#include <memory>

namespace meshprep::cli {
namespace {

struct SimplifyOptions {
  std::string input, output, json, cost = "quadric";
  double ratio = 0;
  std::size_t faces = 0;
};

int run_simplify(const SimplifyOptions& o) {
  ensure_not_input(o.output, o.input);
  ensure_not_input(o.json, o.input);
  if ((o.ratio > 0) == (o.faces > 0)) throw InvalidInput("give exactly one of --ratio and --faces");
  LoadedMesh loaded = load_mesh(o.input);
  if (!loaded.build.dropped_faces.empty())
    std::cerr << "meshprep: warning: " << o.input << ": " << loaded.build.dropped_faces.size()
              << " faces make an edge or vertex non-manifold and are left out (first: face "
              << loaded.build.dropped_faces.front() << ")\n";
  SimplifyParams params;
  params.keep_ratio = o.ratio > 0 ? o.ratio : 1.0;
  params.target_faces = o.faces;
  const SimplifyResult result = simplify(loaded.mesh, params);
  const TriangleSoup output = soup_from_mesh(loaded.mesh);
  write_soup(output, o.output);

  QualityParams quality_params;
  QualityReport quality = analyze_quality(output, quality_params, &loaded.soup);
  quality.path = o.output;
  quality.reference->path = o.input;
  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["output"] = o.output;
  json["cost"] = o.cost;
  json["faces_before"] = result.faces_before;
  json["faces_after"] = result.faces_after;
  json["target_faces"] = result.target_faces;
  json["reached_target"] = result.reached_target;
  json["time_seconds"] = result.seconds;
  json["dropped_input_faces"] = loaded.build.dropped_faces.size();
  json["quality"] = to_json(quality);
  if (!o.json.empty()) emit_json(json, o.json);
  if (o.json != "-")
    std::cout << o.input << " -> " << o.output << ": " << result.faces_before << " -> " << result.faces_after
              << " faces in " << result.seconds << " s; Hausdorff " << quality.reference->hausdorff_relative
              << " of the diagonal, min angle < 20 deg on " << 100 * quality.faces_min_angle_below_20
              << " % of faces, radius ratio p95 " << quality.radius_ratio.p95 << '\n';
  return kSuccess;
}

}  // namespace

Action add_simplify_command(CLI::App& app) {
  auto o = std::make_shared<SimplifyOptions>();
  CLI::App* cmd = app.add_subcommand("simplify", "Reduce a surface mesh to a target size by edge collapse");
  cmd->add_option("input", o->input, "Surface mesh")->required();
  cmd->add_option("-o,--output", o->output, "Simplified surface (.off .obj .ply .stl)")->required();
  auto* ratio = cmd->add_option("--ratio", o->ratio, "Fraction of the faces kept, in (0, 1]")
                    ->check(CLI::Range(1e-9, 1.0));
  cmd->add_option("--faces", o->faces, "Target number of faces")->check(CLI::PositiveNumber)->excludes(ratio);
  cmd->add_option("--cost", o->cost,
                  "Collapse cost: quadric (OpenMesh's quadric decimater, the baseline; the paper's bending "
                  "energy is not in yet)")
      ->check(CLI::IsMember({"quadric"}))
      ->capture_default_str();
  cmd->add_option("--json", o->json, "Write the results and the quality of the output (against the input) as JSON");
  return [o] { return run_simplify(*o); };
}

}  // namespace meshprep::cli
