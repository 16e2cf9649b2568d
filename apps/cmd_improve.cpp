// meshprep improve TETS -o OUT [--tet-quality default|high] [--goal-min-dihedral DEG] [--goal-max-dihedral DEG]
//   [--improve-time-limit S] [--msh-version 4.1|2.2] [--binary | --ascii] [--target NAME]
//   [--min-dihedral-threshold DEG] [--max-dihedral-threshold DEG] [--max-inverted-tets N]
//   [--threads N] [--order 1|2 [--reference SURFACE]] [--json FILE|-]
// Anyone's tet mesh (Gmsh, VTK, Medit, TetGen files) improved with the boundary kept exactly:
// the quality before and after, the verdict, the same formats out as tetrahedralize writes. The
// improvement moves linear tets: --order 2 makes them second-order afterwards.
#include "cli_common.h"
#include "interrupt.h"
#include "tet_second_order.h"

#include "meshprep/commands/tet_commands.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/fem/export.h"
#include "meshprep/fem/import.h"
#include "meshprep/fem/tet_quality.h"

#include <iostream>
#include <memory>
#include <optional>

namespace meshprep::cli {
namespace {

struct ImproveOptions {
  std::string input, output, json, target, reference, msh_version = "4.1";
  EncodingFlags encoding;
  ImproveFlags improve;
  ElementOrderParams element_order;
  ThresholdFlags thresholds;
  std::size_t threads = 0;
};

void print_quality(const char* label, const TetQualityReport& q) {
  std::cout << "  " << label << ": " << q.tetrahedra << " tets, smallest dihedral " << q.min_dihedral_deg.min
            << " deg, largest " << q.max_dihedral_deg.max << " deg, under 10 deg " << 100 * q.tets_min_dihedral_below_10
            << " %, inverted " << q.inverted_tets << '\n';
}

int run_improve(const ImproveOptions& o) {
  const ThreadLimit parallelism(o.threads);
  check_output_files({o.input, o.reference}, {o.output, o.json});
  const TetExportOptions options = tet_export_options(o.output, o.target, o.msh_version, o.encoding);
  if (!is_tet_mesh_path(o.input))
    throw InvalidInput(o.input + ": not a tet mesh file (" + tet_mesh_extensions() + "); for a surface use "
                       "meshprep tetrahedralize");
  TetReadReport read;
  TetMesh tets = read_tet_mesh(o.input, &read);
  const std::optional<TriangleSoup> reference =
      o.element_order.order == 2 && !o.reference.empty() ? std::optional(read_soup(o.reference)) : std::nullopt;
  TetFinishing finishing;
  finishing.improve_params = o.improve.applied_to({});
  finishing.element_order = o.element_order;
  finishing.thresholds = o.thresholds.applied_to({});
  TetOutcome outcome;
  try {
    outcome = improve_command(std::move(tets), reference ? &*reference : nullptr, finishing, {o.input, o.output},
                              terminal_hooks());
  } catch (const Cancelled&) {
    if (stop_requested()) throw Cancelled(o.input + ": " + stop_reason() + "; nothing written");
    throw;  // the time limit: main says so
  }
  print_messages(outcome.messages);
  TetExportReport written;
  write_tet_mesh(outcome.tets, o.output, options, &written);
  note_export_rounding(o.output, written);
  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["format"] = read.format;
  json["output"] = o.output;
  json.update(outcome.report);
  if (!o.json.empty()) emit_json(json, o.json);
  if (o.json != "-") {
    std::cout << o.input << " (" << read.format << ") -> " << o.output << '\n';
    print_quality("before", *outcome.quality_before);
    print_quality("after ", outcome.quality);
    std::cout << "  improved: " << improvement_summary(*outcome.improvement) << '\n';
    if (outcome.second_order) std::cout << "  second order: " << second_order_summary(*outcome.second_order) << '\n';
    if (outcome.fem_ready()) std::cout << "  FEM-ready: every threshold holds\n";
  }
  if (outcome.fem_ready()) return kSuccess;
  print_failed_thresholds(o.input, outcome.verdict.checks, &*outcome.improvement);
  throw NotReady(o.input + ": not FEM-ready: the tets fail " + failed_names(outcome.verdict) + " (above); " + o.output +
                   " is written");
}

}  // namespace

Action add_improve_command(CLI::App& app) {
  auto o = std::make_shared<ImproveOptions>();
  CLI::App* cmd = app.add_subcommand(
      "improve", "Improve a tet mesh's worst tets (flips, smoothing, new inner vertices); the boundary is kept exactly "
                 "unless --boundary-deviation lets its vertices slide on it");
  cmd->add_option("tets", o->input, "Tet mesh: .msh (2.2, 4.1) .vtu .vtk .mesh .node/.ele .xdmf")->required();
  cmd->add_option("-o,--output", o->output, "Improved tet mesh: .msh .vtu .vtk .mesh .node .inp .xdmf (format from the extension)")
      ->required();
  cmd->add_option("--msh-version", o->msh_version, "Gmsh format version for .msh")
      ->check(CLI::IsMember({"4.1", "2.2"}))
      ->capture_default_str();
  add_encoding_options(*cmd, o->encoding, "Binary .msh (.vtu is binary unless --ascii, .xdmf always)");
  cmd->add_option("--target", o->target, "Write what a solver reads: mfem, fenicsx, dealii, calculix, code_aster");
  add_improve_options(*cmd, o->improve, /*can_switch_off=*/false);
  add_threshold_options(*cmd, o->thresholds);
  CLI::Option* order = add_order_option(*cmd, o->element_order);
  add_reference_option(*cmd, o->reference)->needs(order);
  add_threads_option(*cmd, o->threads);
  cmd->add_option("--json", o->json, "Write the quality before and after, and the verdict, as JSON to FILE ('-' = stdout)");
  return [o] { return run_improve(*o); };
}

}  // namespace meshprep::cli
