// meshprep convert IN -o OUT [--binary | --ascii] [--msh-version 4.1|2.2] [--order 1|2 [--reference
// SURFACE]] [--json FILE|-]: between the surface formats, or between the tet mesh formats, without
// changing the mesh but for its order when --order asks for another (2: make_quadratic; 1: the
// corner tets); or from a tet mesh to a surface format: its boundary surface, with its patches.
// (OUT may also come second, as before -o was added.)
#include "cli_common.h"
#include "cli_parameters.h"
#include "tet_report.h"
#include "tet_second_order.h"

#include "meshprep/core/errors.h"
#include "meshprep/commands/tet_commands.h"
#include "meshprep/core/io.h"
#include "meshprep/fem/export.h"
#include "meshprep/fem/fem_parameters.h"
#include "meshprep/fem/import.h"
#include "meshprep/fem/tet_boundary.h"

#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <vector>

namespace meshprep::cli {
namespace {

struct ConvertOptions {
  std::string input, output, json, reference, msh_version = "4.1";
  EncodingFlags encoding;
  std::optional<std::size_t> order;  ///< unset: the input's
};

// The line on stdout (unless the JSON goes there) and the JSON file.
void report(const ConvertOptions& o, const nlohmann::ordered_json& counts, const std::string& line) {
  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["output"] = o.output;
  json.update(counts);
  if (!o.json.empty()) emit_json(json, o.json);
  if (o.json != "-") std::cout << o.input << " -> " << o.output << ": " << line << '\n';
}

// The files a TetGen path stands for (.node, .ele, .face), or the path alone.
// A format cannot hold what the input has (e.g. a tet mesh to a surface format): name both.
template <class Write>
void write_naming_both(const ConvertOptions& o, Write write) {
  try {
    write();
  } catch (const InvalidInput& e) {
    throw InvalidInput(o.input + " -> " + e.what());
  }
}

// The mesh in the order asked: a linear one made second-order onto the reference (the tets' own
// boundary without one), a second-order one reduced to its corner tets.
std::optional<QuadraticResult> change_order(const ConvertOptions& o, TetMesh& mesh, nlohmann::ordered_json& counts) {
  const std::size_t order = mesh.quadratic() ? 2 : 1;
  if (!o.order || *o.order == order) return std::nullopt;
  if (*o.order == 1) {
    mesh = linear_mesh(mesh);
    return std::nullopt;
  }
  const std::optional<TriangleSoup> reference = o.reference.empty() ? std::nullopt : std::optional(read_soup(o.reference));
  CommandMessages messages;
  QuadraticResult result = make_second_order(mesh, reference ? &*reference : nullptr, counts, messages, terminal_hooks());
  print_messages(messages);
  return result;
}

// --binary for a surface format that is text only (OFF, OBJ), refused before any work; --ascii
// asks what every surface writer does unless --binary.
void check_surface_encoding(const ConvertOptions& o) {
  const std::string extension = extension_of(o.output);
  if (o.encoding.binary && (extension == "off" || extension == "obj"))
    throw InvalidInput(o.output + ": cannot write " + (extension == "off" ? "OFF" : "OBJ") +
                       " binary: it is a text format (binary: .ply .stl)");
}

// A tet mesh's boundary surface (its corner faces), with its tags as patches where the format holds
// them (OBJ groups, PLY's patch property, ASCII STL's solids; not OFF or binary STL).
int extract_boundary(const ConvertOptions& o) {
  check_output_files({o.input}, {o.output, o.json});
  if (o.order) throw InvalidInput("convert: --order applies to tet outputs, not to the surface " + o.output);
  check_surface_encoding(o);
  TetReadReport read;
  const TetMesh mesh = read_tet_mesh(o.input, &read);
  note_read_changes(read);
  const TriangleSoup boundary = boundary_surface(mesh);
  WriteOptions options;
  options.binary = o.encoding.binary;
  write_naming_both(o, [&] { write_soup(boundary, o.output, options); });
  std::set<int> patches(boundary.patches.begin(), boundary.patches.end());
  report(o, {{"kind", "boundary"}, {"vertices", boundary.points.size()}, {"triangles", boundary.triangles.size()},
             {"patches", patches.size()}},
         "the boundary of " + std::to_string(mesh.tets.size()) + " tets: " + std::to_string(boundary.points.size()) +
             " vertices, " + std::to_string(boundary.triangles.size()) + " triangles, " + std::to_string(patches.size()) +
             (patches.size() == 1 ? " patch" : " patches"));
  return kSuccess;
}

int convert_tet_mesh(const ConvertOptions& o) {
  if (is_surface_mesh_path(o.output)) return extract_boundary(o);
  check_output_files({o.input, o.reference}, {o.output, o.json});
  TetExportOptions options;  // checked before the input is read: binary .inp is bad usage, whatever the input
  write_naming_both(o, [&] { options = tet_export_options(o.output, "", o.msh_version, o.encoding); });
  TetReadReport read;
  TetMesh mesh = read_tet_mesh(o.input, &read);
  note_read_changes(read);
  nlohmann::ordered_json counts = {{"kind", "tets"}};
  const std::optional<QuadraticResult> second_order = change_order(o, mesh, counts);
  TetExportReport written;
  write_naming_both(o, [&] { write_tet_mesh(mesh, o.output, options, &written); });
  note_export_rounding(o.output, written);
  counts["order"] = mesh.quadratic() ? 2 : 1;
  counts["points"] = mesh.points.size();
  counts["tets"] = mesh.tets.size();
  counts["boundary_faces"] = mesh.boundary_faces.size();
  std::string line = std::to_string(mesh.points.size()) + " points, " + std::to_string(mesh.tets.size()) +
                     (mesh.quadratic() ? " 10-node" : "") + " tets, " + std::to_string(mesh.boundary_faces.size()) +
                     " boundary faces";
  if (second_order) line += "\n  second order: " + second_order_summary(*second_order);
  report(o, counts, line);
  return kSuccess;
}

int convert_surface(const ConvertOptions& o) {
  check_output_files({o.input}, {o.output, o.json});
  check_surface_encoding(o);
  ReadReport read;
  const TriangleSoup soup = read_soup(o.input, &read);
  WriteOptions options;
  options.binary = o.encoding.binary;
  write_naming_both(o, [&] { write_soup(soup, o.output, options); });
  std::string line = std::to_string(soup.points.size()) + " vertices, " + std::to_string(soup.triangles.size()) + " triangles";
  if (read.polygons_triangulated > 0) line += " (" + std::to_string(read.polygons_triangulated) + " polygons triangulated)";
  report(o, {{"kind", "surface"}, {"vertices", soup.points.size()}, {"triangles", soup.triangles.size()},
             {"polygons_triangulated", read.polygons_triangulated}},
         line);
  return kSuccess;
}

}  // namespace

Action add_convert_command(CLI::App& app) {
  auto o = std::make_shared<ConvertOptions>();
  CLI::App* cmd = app.add_subcommand("convert",
                                     "Convert a surface mesh between OFF, OBJ, PLY and STL, or a tet mesh from .msh .vtu .vtk "
                                     ".mesh .node .xdmf to those and .inp, or to its boundary surface (.off .obj .ply .stl, "
                                     "with its patches where the format holds them) (format from the extension)");
  cmd->add_option("input", o->input, "Input surface or tet mesh (a TetGen mesh by its .node or .ele)")->required();
  auto* output = cmd->add_option("-o,--output", o->output, "Output mesh of the same kind, or a tet mesh's boundary surface");
  cmd->add_option("output", o->output, "The output, as the second argument instead of -o")->excludes(output);
  add_encoding_options(*cmd, o->encoding,
                       "Binary PLY, STL or .msh instead of ASCII (.vtu is binary unless --ascii, .xdmf always)");
  cmd->add_option("--msh-version", o->msh_version, "Gmsh format version for a .msh output")
      ->check(CLI::IsMember({"4.1", "2.2"}))
      ->capture_default_str();
  const ParameterInfo& order = element_order_parameters().order;
  CLI::Option* order_option = cmd->add_option(order.flag, o->order, capitalised(order.help) + " (default: the input's)")
                                  ->check(range_check(order.range));
  add_reference_option(*cmd, o->reference)->needs(order_option);
  cmd->add_option("--json", o->json, "Write what was converted (counts) as JSON (- for standard output)");
  return [o] {
    if (o->output.empty()) throw InvalidInput("convert: give the output file with -o OUT");
    if (o->order && !is_tet_mesh_path(o->input)) throw InvalidInput("convert: --order applies to tet meshes, not to " + o->input);
    return is_tet_mesh_path(o->input) ? convert_tet_mesh(*o) : convert_surface(*o);
  };
}

}  // namespace meshprep::cli
