// meshprep quality MESH [--reference REF] [--json FILE|-] [--csv FILE] [--vtk FILE] [--html FILE]
//                       [--fail-on CONDITIONS] [--worst N] [--samples N] [--threads N]
// MESH is a surface (.off .obj .ply .stl) or a tet mesh (.msh .vtu .vtk .mesh .node .ele .xdmf); a tet
// mesh has the text summary and --json (tet_report.h), not the surface-only outputs.
#include "cli_common.h"
#include "tet_report.h"

#include "meshprep/core/errors.h"
#include "meshprep/commands/tet_mesh_report.h"
#include "meshprep/core/io.h"
#include "meshprep/fem/import.h"
#include "meshprep/quality/quality_gate.h"
#include "meshprep/quality/report.h"
#include "meshprep/report/report_writers.h"

#include <filesystem>
#include <iostream>
#include <memory>
#include <utility>

namespace meshprep::cli {
namespace {

struct QualityOptions {
  std::string input, reference, json, csv, vtk, html, fail_on;
  std::size_t worst = 10;
  std::size_t samples = QualityParams().distance_samples;
  std::size_t threads = 0;
};

// Faces a halfedge mesh cannot hold (non-manifold, oriented against a neighbour, repeated):
// the processing stages would refuse the surface, so the user hears about it here, with the indices.
// OpenMesh refuses a face only at a complex edge or vertex (or a patch it cannot relink there),
// which a manifold, oriented soup without duplicate faces does not have, in any face order: such
// a surface is not built again to be told so (at 1.2 M faces, 14 % of the command's time).
nlohmann::ordered_json describe_input(const TriangleSoup& soup, const ReadReport& read, const QualityReport& report) {
  MeshBuildReport build;
  if (!(report.manifold && report.oriented && report.duplicate_faces == 0)) mesh_from_soup(soup, &build);
  nlohmann::ordered_json j;
  j["format"] = read.format;
  j["faces_in_file"] = read.faces_in_file;
  j["polygons_triangulated"] = read.polygons_triangulated;
  j["faces_not_manifold_representable"] = build.dropped_faces.size();
  j["faces_not_manifold_representable_indices"] = build.dropped_faces;
  if (read.polygons_triangulated > 0)
    std::cerr << "meshprep: note: " << read.path << ": " << read.polygons_triangulated
              << " polygons with more than 3 corners were fan-triangulated\n";
  if (!build.dropped_faces.empty()) {
    std::cerr << "meshprep: warning: " << read.path << ": " << dropped_faces_problem(soup, build)
              << "; the processing stages would refuse the surface (faces";
    for (std::size_t i = 0; i < build.dropped_faces.size() && i < 10; ++i) std::cerr << ' ' << build.dropped_faces[i];
    std::cerr << (build.dropped_faces.size() > 10 ? " ...)\n" : ")\n");
  }
  return j;
}

// Exit 1 with the conditions of the gate that hold, else 0.
int apply_gate(const std::vector<GateCondition>& gate, const nlohmann::ordered_json& json) {
  const auto failed = failed_conditions(gate, json);
  if (failed.empty()) return kSuccess;
  std::cerr << "meshprep: quality gate failed:";
  for (const auto& c : failed) std::cerr << ' ' << c.text << " (is " << c.actual.dump() << ')';
  std::cerr << '\n';
  return kNotReady;
}

int run_tet_quality(const QualityOptions& o, const std::vector<GateCondition>& gate) {
  const std::pair<const std::string*, const char*> surface_only[] = {
      {&o.reference, "--reference"}, {&o.csv, "--csv"}, {&o.vtk, "--vtk"}, {&o.html, "--html"}};
  for (const auto& [value, option] : surface_only)
    if (!value->empty())
      throw InvalidInput(std::string(option) + " is for surface meshes and " + o.input +
                         " is a tet mesh (its report: the text summary, or --json)");
  check_output_files({o.input}, {o.json});
  TetReadReport read;
  const TetMesh mesh = read_tet_mesh(o.input, &read);
  note_read_changes(read);
  const nlohmann::ordered_json json = tet_mesh_report(mesh, read);
  if (!o.json.empty()) emit_json(json, o.json);
  if (o.json != "-") write_tet_summary(std::cout, json);
  return apply_gate(gate, json);
}

int run_quality(const QualityOptions& o) {
  const ThreadLimit parallelism(o.threads);
  // Parse the gate first: a typo in it is a usage error, found before any work.
  std::vector<GateCondition> gate;
  if (!o.fail_on.empty()) gate = parse_quality_gate(o.fail_on);
  if (is_tet_mesh_path(o.input)) return run_tet_quality(o, gate);
  if (!is_surface_mesh_path(o.input) && !std::filesystem::is_directory(o.input)) {
    const std::string extension = extension_of(o.input);
    throw InvalidInput(o.input + ": " + (extension.empty() ? "no file extension" : "unknown extension '." + extension + "'") +
                       " (quality reads surfaces: .off, .obj, .ply, .stl; and tet meshes: " + tet_mesh_extensions() + ")");
  }

  check_output_files({o.input, o.reference}, {o.json, o.csv, o.vtk, o.html});
  ReadReport read;
  const TriangleSoup soup = read_soup(o.input, &read);
  std::unique_ptr<TriangleSoup> reference;
  if (!o.reference.empty()) reference = std::make_unique<TriangleSoup>(read_soup(o.reference));

  QualityParams params;
  params.worst_faces = o.worst;
  params.distance_samples = o.samples;
  QualityReport report = analyze_quality(soup, params, reference.get());
  report.path = o.input;
  if (report.reference) report.reference->path = o.reference;

  nlohmann::ordered_json json = to_json(report);
  json["input"] = describe_input(soup, read, report);
  if (!o.csv.empty()) write_csv(o.csv, soup, report);
  if (!o.vtk.empty()) write_vtk(o.vtk, soup, report);
  if (!o.html.empty()) write_html(o.html, soup, report);
  if (!o.json.empty()) emit_json(json, o.json);
  if (o.json != "-") write_text_summary(std::cout, report);
  return apply_gate(gate, json);
}

}  // namespace

Action add_quality_command(CLI::App& app) {
  auto o = std::make_shared<QualityOptions>();
  CLI::App* cmd = app.add_subcommand(
      "quality", "Measure a surface mesh (topology, triangle shape, distance to a reference) or a tet mesh (tet shape, boundary)");
  cmd->add_option("mesh", o->input, "Surface mesh (.off .obj .ply .stl) or tet mesh (.msh .vtu .vtk .mesh .node .ele .xdmf)")
      ->required();
  cmd->add_option("--reference", o->reference,
                  "Reference surface: adds Hausdorff/RMS/mean distance and volume change (surfaces only)");
  add_threads_option(*cmd, o->threads);
  cmd->add_option("--json", o->json, "Write the report as JSON to FILE ('-' = stdout, replaces the table)");
  cmd->add_option("--csv", o->csv, "Write one row per face to FILE (surfaces only)");
  cmd->add_option("--vtk", o->vtk, "Write the mesh with per-face metrics as cell data and the surface variation "
                  "of each vertex as point data (legacy VTK, for ParaView; surfaces only)");
  cmd->add_option("--html", o->html,
                  "Write a self-contained HTML report with pictures of the surface and histograms (surfaces only)");
  cmd->add_option("--fail-on", o->fail_on,
                  "Quality gate: exit 1 if any condition holds, e.g. \"radius_ratio.p95>3,closed=false\"");
  cmd->add_option("--worst", o->worst, "How many worst faces to list (surfaces)")->capture_default_str();
  add_samples_option(*cmd, o->samples);
  return [o] { return run_quality(*o); };
}

}  // namespace meshprep::cli
