// meshprep reconstruct POINTS.xyz -o MESH [--resolution NX NY | --spacing H] [--leaf-size K]
//   [--neighbors N] [--max-gap G] [--json FILE|-]
#include "cli_common.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/preprocess/reconstruct.h"

#include <chrono>
#include <iostream>
#include <memory>
#include <vector>

namespace meshprep::cli {
namespace {

struct ReconstructOptions {
  std::string input, output, json;
  std::vector<std::size_t> resolution{300, 300};
  double spacing = 0, max_gap = 0;
  std::size_t leaf_size = 16, neighbors = 40;
};

int run_reconstruct(const ReconstructOptions& o) {
  ensure_not_input(o.output, o.input);
  ensure_not_input(o.json, o.input);
  const PointSet input = read_points(o.input);
  ReconstructParams params;
  params.columns = o.resolution[0];
  params.rows = o.resolution[1];
  params.spacing = o.spacing;
  params.max_gap = o.max_gap;
  params.fit.leaf_size = o.leaf_size;
  params.fit.neighbors = o.neighbors;
  const auto start = std::chrono::steady_clock::now();
  ReconstructResult result;
  try {
    result = reconstruct_surface(input.points, params);
  } catch (const InvalidInput& e) {
    throw InvalidInput(o.input + ": " + e.what());
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (result.mesh.triangles.empty())
    throw WorkFailed(o.input + ": every triangle is farther than --max-gap " + std::to_string(result.max_gap) +
                     " from the samples; nothing written");
  write_soup(result.mesh, o.output);

  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["output"] = o.output;
  json["points"] = input.points.size();
  json["vertices"] = result.mesh.points.size();
  json["faces"] = result.mesh.triangles.size();
  json["patches"] = result.patches;
  json["leaf_size"] = o.leaf_size;
  json["neighbors"] = o.neighbors;
  json["max_gap"] = result.max_gap;
  json["gap_faces_left_out"] = result.gap_triangles;
  json["reference_normal"] = {result.normal.x(), result.normal.y(), result.normal.z()};
  json["time_seconds"] = seconds;
  if (!o.json.empty()) emit_json(json, o.json);
  if (o.json != "-")
    std::cout << o.input << " -> " << o.output << ": " << input.points.size() << " points, "
              << result.mesh.points.size() << " vertices, " << result.mesh.triangles.size() << " faces ("
              << result.gap_triangles << " left out over gaps wider than " << result.max_gap << ") in " << seconds
              << " s\n";
  return kSuccess;
}

}  // namespace

Action add_reconstruct_command(CLI::App& app) {
  auto o = std::make_shared<ReconstructOptions>();
  CLI::App* cmd = app.add_subcommand(
      "reconstruct", "Scattered points (a height field over a disc-like domain) -> triangle mesh, by an RBF partition of unity");
  cmd->add_option("input", o->input, "Point set (.xyz)")->required();
  cmd->add_option("-o,--output", o->output, "Surface mesh (.off .obj .ply .stl)")->required();
  auto* resolution = cmd->add_option("--resolution", o->resolution, "Grid vertices along the footprint: NX NY")
                         ->expected(2)
                         ->check(CLI::Range(std::size_t(2), std::size_t(100000)))
                         ->capture_default_str();
  cmd->add_option("--spacing", o->spacing, "Grid spacing in the reference plane (instead of --resolution)")
      ->check(CLI::PositiveNumber)
      ->excludes(resolution);
  cmd->add_option("--leaf-size", o->leaf_size, "K: samples per k-d tree cell (one local patch each)")
      ->check(CLI::Range(std::size_t(1), std::size_t(100000)))
      ->capture_default_str();
  cmd->add_option("--neighbors", o->neighbors, "Samples interpolated by each cell's thin-plate patch")
      ->check(CLI::Range(std::size_t(3), std::size_t(1000)))
      ->capture_default_str();
  cmd->add_option("--max-gap", o->max_gap,
                  "Leave out triangles farther than this from every sample (0 = 3x the median sample spacing)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--json", o->json, "Write the results as JSON (- for standard output)");
  return [o] { return run_reconstruct(*o); };
}

}  // namespace meshprep::cli
