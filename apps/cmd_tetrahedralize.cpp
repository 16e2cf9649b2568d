// meshprep tetrahedralize SURFACE -o OUT [--radius-edge R] [--min-dihedral DEG]
//   [--max-volume V | --max-volume-relative F] [--keep-surface] [--msh-version 4.1|2.2] [--binary | --ascii]
//   [--target NAME] [--diagnose FILE] [--extrude-base DEPTH | --extrude-base-relative F]
//   [--size H] [--size-min H] [--size-max H] [--grading G] [--curvature-points N] [--thickness-layers K]
//   [--fem-check] [--no-improve] [--tet-quality default|high] [--goal-min-dihedral DEG] [--goal-max-dihedral DEG]
//   [--improve-time-limit S] [--min-dihedral-threshold DEG] [--max-dihedral-threshold DEG] [--max-inverted-tets N]
//   [--time-limit S] [--threads N] [--order 1|2] [--json FILE|-]
#include "cli_common.h"
#include "cli_parameters.h"
#include "interrupt.h"
#include "tet_second_order.h"

#include "meshprep/commands/tet_commands.h"
#include "meshprep/core/io.h"
#include "meshprep/fem/export.h"
#include "meshprep/fem/fem_check.h"
#include "meshprep/fem/fem_parameters.h"
#include "meshprep/fem/prepare_plc.h"
#include "meshprep/preprocess/patches/patches.h"
#include "meshprep/preprocess/patches/patches_parameters.h"
#include "meshprep/fem/readiness.h"
#include "meshprep/fem/solver_targets.h"
#include "meshprep/fem/tet_quality.h"
#include "meshprep/fem/tetrahedralize.h"
#include "meshprep/quality/surface_distance.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <utility>

namespace meshprep::cli {
namespace {

struct TetOptions {
  std::string input, output, json, target, diagnose, msh_version = "4.1";
  TetrahedralizeCommand command;  ///< its improvement's goals and thresholds come from the flags below
  ThresholdFlags thresholds;
  ImproveFlags improve;
  SizeFlags size;
  EncodingFlags encoding;
  std::size_t threads = 0;
};

// A surface that is not FEM-ready: its faces in --diagnose's file, one line per problem, exit 2
// (the input cannot be tetrahedralized; found before TetGen runs).
[[noreturn]] void fail_unready(const TetOptions& o, const TriangleSoup& soup, const Readiness& readiness,
                               const std::string& failure) {
  if (!o.diagnose.empty()) write_soup(diagnosis_mesh(soup, readiness), o.diagnose);
  for (const ReadinessProblem& p : readiness.problems) {
    std::string faces;
    for (std::size_t i = 0; i < p.faces.size() && i < 8; ++i) faces += (i ? " " : "") + std::to_string(p.faces[i]);
    std::cerr << "meshprep: " << o.input << ": not FEM-ready: " << p.check << ": " << p.what << " (faces " << faces
              << (p.faces.size() > 8 ? " ..." : "") << "); " << p.hint << '\n';
  }
  throw InvalidInput(o.input + ": " + failure +
                   (o.diagnose.empty() ? "; --diagnose FILE writes the offending faces" : "; offending faces in " + o.diagnose));
}

int run_tetrahedralize(const TetOptions& o) {
  const ThreadLimit parallelism(o.threads);
  check_output_files({o.input}, {o.output, o.json, o.diagnose});
  check_tet_params(o.command.params);  // a bound TetGen cannot meet is bad usage, whatever the surface
  const TetExportOptions options = tet_export_options(o.output, o.target, o.msh_version, o.encoding);
  const TriangleSoup soup = read_soup(o.input);
  TetrahedralizeCommand command = o.command;
  command.finishing.improve = !o.improve.off;
  command.finishing.improve_params = o.improve.applied_to({});
  command.size = o.size.applied_to({});
  command.finishing.thresholds = o.thresholds.applied_to({});
  TetOutcome outcome;
  try {
    outcome = tetrahedralize_command(soup, command, {o.input, o.output}, terminal_hooks());
  } catch (const Cancelled&) {
    if (stop_requested()) throw Cancelled(o.input + ": " + stop_reason() + "; nothing written");
    throw;  // the time limit: main says so
  }
  print_messages(outcome.messages);
  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["output"] = o.output;
  json.update(outcome.report);
  if (!outcome.failure.empty()) {
    if (!o.json.empty()) emit_json(json, o.json);
    if (outcome.readiness && !outcome.readiness->ready()) fail_unready(o, soup, *outcome.readiness, outcome.failure);
    throw SolverError(o.input + ": " + outcome.failure);
  }
  TetExportReport written;
  write_tet_mesh(outcome.tets, o.output, options, &written);
  note_export_rounding(o.output, written);
  if (!o.json.empty()) emit_json(json, o.json);
  const TetQualityReport& quality = outcome.quality;
  if (o.json != "-") {
    std::cout << o.input << " -> " << o.output << ": " << quality.tetrahedra << " tets, " << quality.points
              << " points, volume " << quality.volume << "\n  min dihedral " << quality.min_dihedral_deg.min
              << " deg, tets under 10 deg " << 100 * quality.tets_min_dihedral_below_10 << " %, radius-edge max "
              << quality.radius_edge_ratio.max << ", scaled Jacobian min " << quality.scaled_jacobian.min << '\n';
    if (outcome.improvement) std::cout << "  improved: " << improvement_summary(*outcome.improvement) << '\n';
    if (outcome.second_order) std::cout << "  second order: " << second_order_summary(*outcome.second_order) << '\n';
    if (outcome.fem_ready()) std::cout << "  FEM-ready: every threshold holds\n";
    if (o.command.fem_check) {
      const auto& f = json["fem_check"];
      std::cout << "  FEM check: patch test error " << f["patch_test_max_error"] << ", Poisson L2 error "
                << f["poisson_l2_error"] << '\n';
    }
  }
  if (outcome.fem_ready()) return kSuccess;
  print_failed_thresholds(o.input, outcome.verdict.checks, outcome.improvement ? &*outcome.improvement : nullptr);
  throw NotReady(o.input + ": not FEM-ready: the tets fail " + failed_names(outcome.verdict) + " (above); " + o.output +
                   " is written");
}

}  // namespace

Action add_tetrahedralize_command(CLI::App& app) {
  auto o = std::make_shared<TetOptions>();
  CLI::App* cmd = app.add_subcommand("tetrahedralize", "Tetrahedralise a closed surface with TetGen and export it for a solver");
  cmd->add_option("surface", o->input, "Closed surface mesh (.off .obj .ply .stl)")->required();
  cmd->add_option("-o,--output", o->output,
                  "Tet mesh: .msh .vtu .vtk .mesh .node .inp .xdmf (format from the extension)")->required();
  const TetParameters& p = tet_parameters();
  add_parameter(*cmd, p.radius_edge, o->command.params.radius_edge);
  add_parameter(*cmd, p.min_dihedral_deg, o->command.params.min_dihedral_deg);
  auto* abs_volume = cmd->add_option("--max-volume", o->command.params.max_volume, "Largest tet volume (absolute)")
                         ->check(positive());
  add_parameter(*cmd, p.max_volume_relative, o->command.params.max_volume_relative)->excludes(abs_volume);
  add_parameter(*cmd, p.keep_surface, o->command.params.keep_surface);
  add_size_options(*cmd, o->size);
  cmd->add_option("--msh-version", o->msh_version, "Gmsh format version for .msh")
      ->check(CLI::IsMember({"4.1", "2.2"}))
      ->capture_default_str();
  add_encoding_options(*cmd, o->encoding, "Binary .msh (.vtu is binary unless --ascii, .xdmf always)");
  cmd->add_option("--target", o->target, "Write what a solver reads: mfem, fenicsx, dealii, calculix, code_aster");
  cmd->add_option("--diagnose", o->diagnose, "If the surface is not FEM-ready, write the offending faces to this mesh file");
  auto* depth = cmd->add_option("--extrude-base", o->command.extrude_depth,
                                "Close an open height field into a block with a flat base this far below its lowest point")
                    ->check(positive());
  cmd->add_option("--extrude-base-relative", o->command.extrude_relative, "Same, as a fraction of the bounding-box diagonal")
      ->check(CLI::Range(1e-9, 100.0))
      ->excludes(depth);
  cmd->add_flag("--fem-check", o->command.fem_check, "Solve a P1 Poisson problem with a known solution on the tets and report errors");
  add_improve_options(*cmd, o->improve, /*can_switch_off=*/true);
  add_threshold_options(*cmd, o->thresholds);
  add_auto_parameter(*cmd, patch_parameters().feature_angle_deg, o->command.patches.feature_angle_deg);
  add_patch_edits(*cmd, o->command.patches);
  add_order_option(*cmd, o->command.finishing.element_order);
  add_threads_option(*cmd, o->threads);
  cmd->add_option("--json", o->json, "Write the results as JSON to FILE ('-' = stdout)");
  return [o] { return run_tetrahedralize(*o); };
}

}  // namespace meshprep::cli
