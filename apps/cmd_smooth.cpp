// meshprep smooth IN -o OUT [--method rbf|taubin|laplace] [--neighbors N] [--iterations N]
//   [--smoothing L|inf] [--relaxation F] [--feature-angle DEG] [--preserve-volume] [--threads N]
//   [--json FILE|-]
#include "cli_common.h"
#include "interrupt.h"
#include "progress_bar.h"
#include "stage_failure.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/preprocess/smooth/smooth.h"
#include "meshprep/quality/json_values.h"
#include "meshprep/quality/report.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/triangle_metrics.h"
#include "meshprep/report/report_writers.h"

#include <cmath>
#include <iostream>
#include <map>
#include <memory>

namespace meshprep::cli {
namespace {

const std::map<std::string, SmoothMethod> kMethods = {
    {"rbf", SmoothMethod::Rbf}, {"taubin", SmoothMethod::Taubin}, {"laplace", SmoothMethod::Laplace}};

struct SmoothOptions {
  std::string input, output, json, method = "rbf";
  SmoothParams params;
  std::size_t samples = QualityParams().distance_samples;
  std::size_t threads = 0;
};

int run_smooth(SmoothOptions o) {
  const ThreadLimit parallelism(o.threads);
  ensure_distinct_files({o.input}, {o.output, o.json});
  LoadedMesh loaded = load_mesh(o.input);
  require_all_faces(loaded, "smoothing");
  o.params.method = kMethods.at(o.method);
  ProgressBar bar("smooth");
  o.params.progress = stoppable([&bar](double fraction) { bar.update(fraction); });
  const SmoothResult result = run_stage_on(o.input, [&] { return smooth(loaded.mesh, o.params); });
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
    std::cout << o.input << " -> " << o.output << ": " << o.method << ", " << result.iterations << " iteration(s) in "
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
  cmd->add_option("--method", o->method,
                  "rbf (the paper's: each vertex onto the local RBF surface of its neighbours on its side of "
                  "any feature), taubin or laplace (baselines)")
      ->check(CLI::IsMember({"rbf", "taubin", "laplace"}))
      ->capture_default_str();
  cmd->add_option("--iterations", o->params.iterations, "Smoothing iterations")
      ->check(CLI::Range(std::size_t(1), std::size_t(1000)))
      ->capture_default_str();
  cmd->add_option("--neighbors", o->params.neighbors, "rbf: neighbours of each vertex's local surface")
      ->check(CLI::Range(std::size_t(13), std::size_t(200)))
      ->capture_default_str();
  cmd->add_option("--smoothing", o->params.smoothing,
                  "rbf: lambda of the weighted thin-plate smoothing spline; inf, its limit, is the weighted "
                  "least-squares cubic (0 interpolates the neighbours)")
      ->check(CLI::Validator(
          [](std::string& value) {
            try {
              return std::stod(value) >= 0 ? std::string() : "must be >= 0 (or inf)";
            } catch (const std::exception&) {
              return "expected a number >= 0 or inf, not '" + value + "'";
            }
          },
          "L|inf")
                 .name(kInfinityMeaningful))
      ->capture_default_str();
  cmd->add_option("--relaxation", o->params.relaxation,
                  "rbf: how far each vertex goes towards its 1-ring's centroid before it is put on its local "
                  "surface (evens out the triangles; 0 = along the normal only)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--feature-angle", o->params.feature_angle_deg,
                  "rbf: edges with a larger dihedral angle (degrees) are creases, kept sharp; 180 = none")
      ->check(CLI::Range(1.0, 180.0))
      ->capture_default_str();
  cmd->add_flag("--preserve-volume", o->params.preserve_volume,
                "Closed surfaces: offset the result along its normals so that the enclosed volume is unchanged");
  add_samples_option(*cmd, o->samples);
  add_threads_option(*cmd, o->threads);
  cmd->add_option("--json", o->json, "Write the results and the quality of the output (against the input) as JSON");
  return [o] { return run_smooth(*o); };
}

}  // namespace meshprep::cli
