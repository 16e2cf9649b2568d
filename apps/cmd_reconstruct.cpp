// meshprep reconstruct POINTS.xyz -o MESH [--resolution NX NY | --vertices N | --spacing H]
//   [--leaf-size K] [--neighbors N] [--variation-threshold T|pNN] [--variation-growth G]
//   [--adaptive] [--max-gap G] [--threads N] [--json FILE|-]
#include "cli_common.h"
#include "interrupt.h"
#include "progress_bar.h"
#include "stage_failure.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/preprocess/compose/adaptive_reconstruction.h"
#include "meshprep/preprocess/reconstruct/reconstruct.h"
#include "meshprep/preprocess/reconstruct/variation_rule.h"
#include "meshprep/quality/json_values.h"

#include <chrono>
#include <iostream>
#include <memory>
#include <vector>

namespace meshprep::cli {
namespace {

struct ReconstructOptions {
  std::string input, output, json;
  std::vector<std::size_t> resolution{300, 300};
  double spacing = 0, max_gap = 0, variation_growth = 1.5;
  bool adaptive = false, fill_holes = false;
  std::size_t leaf_size = 16, neighbors = 40, vertices = 0;
  std::size_t threads = 0;
  std::string variation_threshold = "p90";
};

std::string check_variation_rule(const std::string& text) {
  PartitionOfUnityParams scratch;
  return apply_variation_rule(text, scratch) ? std::string() : variation_rule_error(text);
}

int run_reconstruct(const ReconstructOptions& o) {
  const ThreadLimit parallelism(o.threads);
  ensure_distinct_files({o.input}, {o.output, o.json});
  const PointSet input = read_points(o.input);
  ReconstructParams params;
  params.columns = o.resolution[0];
  params.rows = o.resolution[1];
  params.spacing = o.spacing;
  params.vertices = o.vertices;
  params.fill_holes = o.fill_holes;
  params.max_gap = o.max_gap;
  params.fit.leaf_size = o.leaf_size;
  params.fit.neighbors = o.neighbors;
  params.fit.variation_growth = o.variation_growth;
  apply_variation_rule(o.variation_threshold, params.fit);  // checked by CLI11
  ProgressBar bar("reconstruct");
  const AdaptiveReconstructParams adaptive{params, stoppable([&bar](double fraction) { bar.update(fraction); })};
  const auto start = std::chrono::steady_clock::now();
  const ReconstructResult result = run_stage_on(o.input, [&] {
    return o.adaptive ? reconstruct_adaptive(input.points, adaptive) : reconstruct_surface(input.points, params);
  });
  bar.finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (result.mesh.triangles.empty())
    throw WorkFailed(o.input + ": every triangle is farther than --max-gap " + std::to_string(result.max_gap) +
                     " from the samples; nothing written");
  WriteOptions write;
  write.vertex_scalars.push_back({"surface_variation", result.vertex_variation});  // PLY only
  write_soup(result.mesh, o.output, write);

  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["output"] = o.output;
  json["points"] = input.points.size();
  json["vertices"] = result.mesh.points.size();
  json["faces"] = result.mesh.triangles.size();
  json["grid"] = {{"columns", result.columns}, {"rows", result.rows}};
  json["adaptive"] = o.adaptive;
  json["patches"] = result.patches;
  json["leaf_size"] = o.leaf_size;
  json["neighbors"] = o.neighbors;
  json["variation"] = {{"rule", o.variation_threshold},
                       {"threshold", result.variation_threshold},
                       {"growth", o.variation_growth},
                       {"grown_patches", result.grown_patches},
                       {"patch_sigma", json_distribution(summarize(result.patch_variation))},
                       {"vertex_sigma", json_distribution(summarize(result.vertex_variation))}};
  json["max_gap"] = result.max_gap;
  json["gap_faces_left_out"] = result.gap_triangles;
  json["fill_holes"] = o.fill_holes;
  json["filled_faces"] = result.filled_triangles;
  json["reference_normal"] = {result.normal.x(), result.normal.y(), result.normal.z()};
  json["time_seconds"] = seconds;
  if (!o.json.empty()) emit_json(json, o.json);
  if (o.json != "-") {
    std::cout << o.input << " -> " << o.output << ": " << input.points.size() << " points, "
              << result.mesh.points.size() << " vertices, " << result.mesh.triangles.size() << " faces ("
              << result.gap_triangles << " left out over gaps wider than " << result.max_gap;
    if (o.fill_holes) std::cout << "; " << result.filled_triangles << " kept over holes in the data, flagged";
    std::cout << ") in " << seconds << " s\n";
  }
  return kSuccess;
}

}  // namespace

Action add_reconstruct_command(CLI::App& app) {
  auto o = std::make_shared<ReconstructOptions>();
  CLI::App* cmd = app.add_subcommand(
      "reconstruct", "Scattered points (a height field over a disc-like domain) -> triangle mesh, by an RBF partition of unity");
  cmd->add_option("input", o->input, "Point set (.xyz)")->required();
  cmd->add_option("-o,--output", o->output, "Surface mesh (.off .obj .ply .stl; .ply also stores sigma per vertex)")->required();
  auto* resolution = cmd->add_option("--resolution", o->resolution, "Grid vertices along the footprint: NX NY")
                         ->expected(2)
                         ->check(CLI::Range(std::size_t(2), std::size_t(100000)))
                         ->capture_default_str();
  auto* spacing = cmd->add_option("--spacing", o->spacing, "Grid spacing in the reference plane (instead of --resolution)")
                      ->check(CLI::PositiveNumber)
                      ->excludes(resolution);
  cmd->add_option("--vertices", o->vertices, "About this many grid vertices, on square cells (instead of --resolution)")
      ->check(CLI::Range(std::size_t(4), std::size_t(100000000)))
      ->excludes(resolution)
      ->excludes(spacing);
  cmd->add_option("--leaf-size", o->leaf_size, "K: samples per k-d tree cell (one local patch each)")
      ->check(CLI::Range(std::size_t(1), std::size_t(100000)))
      ->capture_default_str();
  cmd->add_option("--neighbors", o->neighbors, "Samples interpolated by each cell's patch (a Duchon r^2.5 spline)")
      ->check(CLI::Range(std::size_t(3), std::size_t(1000)))
      ->capture_default_str();
  cmd->add_option("--variation-threshold", o->variation_threshold,
                  "Patches whose surface variation sigma exceeds this grow (more samples, larger support): a "
                  "value (the paper's 0.3) or a percentile of the patches' sigma (p90)")
      ->check(CLI::Validator(check_variation_rule, "T|pNN"))
      ->capture_default_str();
  cmd->add_option("--variation-growth", o->variation_growth,
                  "Support radius factor of a grown patch (its samples grow by the square)")
      ->check(CLI::Range(1.0, 4.0))
      ->capture_default_str();
  cmd->add_flag("--adaptive", o->adaptive,
                 "Vertices dense where the surface bends, sparse where flat, for about the same face count "
                 "(the twice finer grid simplified back by bending energy; slower)");
  cmd->add_option("--max-gap", o->max_gap,
                  "Leave out triangles farther than this from every sample (0 = 3x the median sample spacing)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_flag("--fill-holes", o->fill_holes,
                "Keep the triangles over gaps inside the footprint (flagged in the JSON) and only the largest "
                "piece, so the surface has one boundary loop and tetrahedralize --extrude-base can close it "
                "into a block (the pipeline does this for points)");
  add_threads_option(*cmd, o->threads);
  cmd->add_option("--json", o->json, "Write the results as JSON (- for standard output)");
  return [o] { return run_reconstruct(*o); };
}

}  // namespace meshprep::cli
