// meshprep tetrahedralize SURFACE -o OUT [--radius-edge R] [--min-dihedral DEG]
//   [--max-volume V | --max-volume-relative F] [--keep-surface] [--msh-version 4.1|2.2] [--binary | --ascii]
//   [--target NAME] [--diagnose FILE] [--extrude-base DEPTH | --extrude-base-relative F]
//   [--fem-check] [--no-improve] [--goal-min-dihedral DEG] [--goal-max-dihedral DEG]
//   [--improve-time-limit S] [--min-dihedral-threshold DEG] [--max-dihedral-threshold DEG] [--max-inverted-tets N]
//   [--timeout SECONDS] [--threads N] [--order 1|2] [--json FILE|-]
#include "cli_common.h"
#include "cli_parameters.h"
#include "interrupt.h"
#include "tet_improvement.h"
#include "tet_second_order.h"

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
  TetParams params;
  ThresholdFlags thresholds;
  ImproveFlags improve;
  PatchParams patches;
  ElementOrderParams element_order;
  double extrude_depth = 0, extrude_relative = 0;
  EncodingFlags encoding;
  bool fem_check = false;
  unsigned timeout = 0;
  std::size_t threads = 0;
};

void progress(const std::string& line) {
  if (::isatty(STDERR_FILENO)) std::cerr << "meshprep: " << line << '\n';
}


// The surface as a PLC (prepare_plc.h): an open height field extruded when asked, else checked.
SurfacePlc prepare_surface(const TetOptions& o, const TriangleSoup& soup, nlohmann::ordered_json& json) {
  std::optional<double> depth;
  if (o.extrude_depth > 0 || o.extrude_relative > 0) {
    depth = o.extrude_depth > 0 ? o.extrude_depth : o.extrude_relative * bbox_diagonal(soup);
    json["extrude_base_depth"] = *depth;
  }
  PreparedPlc prepared = prepare_plc(soup, depth);
  if (depth && !prepared.plc) throw WorkFailed(o.input + ": cannot extrude: " + prepared.extrusion_problem);
  if (depth) return std::move(*prepared.plc);
  const Readiness& readiness = *prepared.readiness;
  json["readiness"] = to_json(readiness);
  if (!readiness.ready()) {
    if (!o.diagnose.empty()) write_soup(diagnosis_mesh(soup, readiness), o.diagnose);
    json["fem_ready"] = false;
    if (!o.json.empty()) emit_json(json, o.json);
    std::string reasons;
    for (const ReadinessProblem& p : readiness.problems) {
      std::string faces;
      for (std::size_t i = 0; i < p.faces.size() && i < 8; ++i) faces += (i ? " " : "") + std::to_string(p.faces[i]);
      std::cerr << "meshprep: " << o.input << ": not FEM-ready: " << p.check << ": " << p.what << " (faces " << faces
                << (p.faces.size() > 8 ? " ..." : "") << "); " << p.hint << '\n';
      reasons += (reasons.empty() ? "" : ", ") + p.check;
    }
    throw WorkFailed(o.input + ": the surface is not FEM-ready (" + reasons + ")" +
                     (o.diagnose.empty() ? "; --diagnose FILE writes the offending faces" : "; offending faces in " + o.diagnose));
  }
  if (readiness.isolated_vertices > 0)
    std::cerr << "meshprep: note: " << o.input << ": " << readiness.isolated_vertices
              << " isolated vertices (no face uses them) are left out of the tets\n";
  if (prepared.flipped_inward) json["flipped_inward_orientation"] = true;
  return std::move(*prepared.plc);
}

int run_tetrahedralize(const TetOptions& o) {
  const ThreadLimit parallelism(o.threads);
  check_output_files({o.input}, {o.output, o.json, o.diagnose});
  check_tet_params(o.params);  // a bound TetGen cannot meet is bad usage, whatever the surface
  const TetExportOptions options = tet_export_options(o.output, o.target, o.msh_version, o.encoding);
  TriangleSoup soup = read_soup(o.input);
  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["output"] = o.output;
  json["order"] = o.element_order.order;
  // The boundary patches, as the pipeline finds them, become the tets' named boundary tags. A
  // surface the halfedge mesh cannot hold has none: the readiness check below says why.
  MeshBuildReport build;
  mesh_from_soup(soup, &build);
  if (build.dropped_faces.empty()) {
    try {
      json["patches"] = to_json(find_patches(soup, o.patches));
    } catch (const InvalidInput& e) {
      throw InvalidInput(o.input + ": " + e.what());
    }
  }
  SurfacePlc plc = prepare_surface(o, soup, json);
  json["switches"] = tetgen_switches(o.params, 0);

  progress("tetrahedralizing " + std::to_string(plc.facets.size()) + " facets with TetGen ...");
  const auto start = std::chrono::steady_clock::now();
  TetMesh tets;
  TetParams params = o.params;
  params.cancelled = stop_requested;
  arm_timeout(o.timeout);
  const auto stopped = [&o] {
    return Cancelled(o.input + ": " + (timed_out() ? "timed out after " + std::to_string(o.timeout) + " s" : stop_reason()) +
                     "; nothing written");
  };
  try {
    tets = tetrahedralize_plc(plc, params);
  } catch (const Cancelled&) {
    throw stopped();
  } catch (const TetgenError& e) {
    json["tetgen_error"] = {{"code", e.code()}, {"message", e.what()}};
    json["fem_ready"] = false;
    if (!o.json.empty()) emit_json(json, o.json);
    throw WorkFailed(o.input + ": " + e.what());
  }
  if (stop_requested()) throw stopped();  // TetGen had just finished
  arm_timeout(0);  // from here on the outputs are written whole
  json["tetgen_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::optional<ImproveResult> improvement;
  if (!o.improve.off) {
    json["tetgen_quality"] = to_json(analyze_tet_quality(tets));
    try {
      improvement = run_improvement(tets, o.improve.applied_to({}), json);
    } catch (const Cancelled&) {
      throw stopped();
    }
  }
  // The improvement keeps the boundary: the change is TetGen's (tetrahedralize.h).
  json["volume_change_relative"] = volume_change_relative(plc, tets);
  if (const std::string note = volume_change_note(json["volume_change_relative"]); !note.empty())
    std::cerr << "meshprep: note: " << o.input << ": " << note << '\n';
  if (o.fem_check) {  // on the linear tets: the check's solve is P1
    progress("FEM check: P1 Poisson solve on " + std::to_string(tets.tets.size()) + " tets ...");
    json["fem_check"] = to_json(run_fem_check(tets));
  }
  std::optional<QuadraticResult> second_order;
  if (o.element_order.order == 2) second_order = make_second_order(tets, &soup, json);
  const TetQualityReport quality = analyze_tet_quality(tets);
  const TetVerdict verdict = judge_tets(quality, o.thresholds.applied_to({}));
  json["tet_quality"] = to_json(quality);
  json["fem_ready"] = verdict.ok();
  json["thresholds"] = to_json(verdict);
  refuse_flat_tets(tets, o.input, o.output);
  TetExportReport written;
  write_tet_mesh(tets, o.output, options, &written);
  note_export_rounding(o.output, written);
  if (!o.json.empty()) emit_json(json, o.json);
  if (o.json != "-") {
    std::cout << o.input << " -> " << o.output << ": " << quality.tetrahedra << " tets, " << quality.points
              << " points, volume " << quality.volume << "\n  min dihedral " << quality.min_dihedral_deg.min
              << " deg, tets under 10 deg " << 100 * quality.tets_min_dihedral_below_10 << " %, radius-edge max "
              << quality.radius_edge_ratio.max << ", scaled Jacobian min " << quality.scaled_jacobian.min << '\n';
    if (improvement) std::cout << "  improved: " << improvement_summary(*improvement) << '\n';
    if (second_order) std::cout << "  second order: " << second_order_summary(*second_order) << '\n';
    if (verdict.ok()) std::cout << "  FEM-ready: every threshold holds\n";
    if (o.fem_check) {
      const auto& f = json["fem_check"];
      std::cout << "  FEM check: patch test error " << f["patch_test_max_error"] << ", Poisson L2 error "
                << f["poisson_l2_error"] << '\n';
    }
  }
  if (verdict.ok()) return kSuccess;
  print_failed_thresholds(o.input, verdict.checks, improvement ? &*improvement : nullptr);
  throw WorkFailed(o.input + ": not FEM-ready: the tets fail " + failed_names(verdict) + " (above); " + o.output +
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
  add_parameter(*cmd, p.radius_edge, o->params.radius_edge);
  add_parameter(*cmd, p.min_dihedral_deg, o->params.min_dihedral_deg);
  auto* abs_volume = cmd->add_option("--max-volume", o->params.max_volume, "Largest tet volume (absolute)")
                         ->check(positive());
  add_parameter(*cmd, p.max_volume_relative, o->params.max_volume_relative)->excludes(abs_volume);
  add_parameter(*cmd, p.keep_surface, o->params.keep_surface);
  cmd->add_option("--msh-version", o->msh_version, "Gmsh format version for .msh")
      ->check(CLI::IsMember({"4.1", "2.2"}))
      ->capture_default_str();
  add_encoding_options(*cmd, o->encoding, "Binary .msh (.vtu is binary unless --ascii, .xdmf always)");
  cmd->add_option("--target", o->target, "Write what a solver reads: mfem, fenicsx, dealii, calculix, code_aster");
  cmd->add_option("--diagnose", o->diagnose, "If the surface is not FEM-ready, write the offending faces to this mesh file");
  auto* depth = cmd->add_option("--extrude-base", o->extrude_depth,
                                "Close an open height field into a block with a flat base this far below its lowest point")
                    ->check(positive());
  cmd->add_option("--extrude-base-relative", o->extrude_relative, "Same, as a fraction of the bounding-box diagonal")
      ->check(CLI::Range(1e-9, 100.0))
      ->excludes(depth);
  cmd->add_flag("--fem-check", o->fem_check, "Solve a P1 Poisson problem with a known solution on the tets and report errors");
  add_improve_options(*cmd, o->improve, /*can_switch_off=*/true);
  add_threshold_options(*cmd, o->thresholds);
  cmd->add_option("--timeout", o->timeout,
                  "Stop TetGen after this many seconds (exit 1, nothing written); Ctrl-C stops it too (exit 130)")
      ->check(CLI::Range(1u, 1000000u));
  add_auto_parameter(*cmd, patch_parameters().feature_angle_deg, o->patches.feature_angle_deg);
  add_patch_edits(*cmd, o->patches);
  add_order_option(*cmd, o->element_order);
  add_threads_option(*cmd, o->threads);
  cmd->add_option("--json", o->json, "Write the results as JSON to FILE ('-' = stdout)");
  return [o] { return run_tetrahedralize(*o); };
}

}  // namespace meshprep::cli
