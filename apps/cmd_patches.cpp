// meshprep patches IN [-o OUT] [--feature-angle A|auto] [--resegment] [--rename OLD=NEW ...]
// [--merge A,B ...] [--json FILE|-]: the boundary patches of a surface, found from its creases
// unless the file names them (preprocess/patches/patches.h), edited, shown as a table and written
// with the surface to a format that holds them.
#include "cli_common.h"
#include "cli_parameters.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/preprocess/patches/patches.h"
#include "meshprep/preprocess/patches/patches_parameters.h"
#include "meshprep/quality/patch_table.h"

#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

namespace meshprep::cli {
namespace {

struct PatchesOptions {
  std::string input, output, json;
  PatchParams params;
};

void print_table(const std::vector<PatchRow>& table, double total_area) {
  std::size_t width = 4;
  for (const PatchRow& row : table) width = std::max(width, row.name.size());
  std::cout << std::left << std::setw(static_cast<int>(width)) << "name" << std::right << std::setw(10) << "faces"
            << std::setw(14) << "area" << std::setw(9) << "area %" << std::setw(16) << "normal spread\n";
  for (const PatchRow& row : table)
    std::cout << std::left << std::setw(static_cast<int>(width)) << row.name << std::right << std::setw(10) << row.faces
              << std::setw(14) << std::setprecision(6) << row.area << std::setw(9) << std::fixed << std::setprecision(2)
              << 100 * row.area / total_area << std::setw(13) << std::setprecision(1) << row.normal_spread_deg
              << " deg\n"
              << std::defaultfloat;
}

// The formats that hold patches (io.h); checked before any work.
void check_output(const std::string& output) {
  if (output.empty()) return;
  const std::string extension = extension_of(output);
  if (extension != "ply" && extension != "obj" && extension != "stl")
    throw InvalidInput(output + ": ." + extension + " holds no patches; write .ply, .obj or .stl (ASCII, one solid per patch)");
}

int run_patches(const PatchesOptions& o) {
  check_output_files({o.input}, {o.output, o.json});
  check_output(o.output);
  ReadReport read;
  TriangleSoup surface = read_soup(o.input, &read);
  PatchResult result;
  try {
    result = find_patches(surface, o.params);
  } catch (const InvalidInput& e) {
    throw InvalidInput(o.input + ": " + e.what());
  }
  const std::vector<PatchRow> table = patch_table(surface);
  double total_area = 0;
  for (const PatchRow& row : table) total_area += row.area;
  if (!o.output.empty()) write_soup(surface, o.output);
  nlohmann::ordered_json json;
  json["input"] = o.input;
  json["output"] = o.output.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(o.output);
  json["from"] = result.segmented ? "creases" : read.patches_from;
  json.update(to_json(result));
  json["table"] = to_json(table);
  if (!o.json.empty()) emit_json(json, o.json);
  if (o.json == "-") return kSuccess;
  std::cout << o.input << ": " << table.size() << " patch" << (table.size() == 1 ? "" : "es") << ", "
            << (result.segmented ? "bounded by the creases sharper than " + parameter_text(result.feature_angle_deg) + " deg"
                                 : "named by the file (" + read.patches_from + ")");
  if (result.merged) std::cout << ", " << result.merged << " merged";
  std::cout << "\n";
  for (const RenamedTag& r : read.renamed_patches) std::cout << "  renamed '" << r.from << "' -> '" << r.to << "' (the file's name)\n";
  for (const RenamedTag& r : result.renamed) std::cout << "  renamed '" << r.from << "' -> '" << r.to << "'\n";
  print_table(table, total_area);
  if (!o.output.empty()) std::cout << "written to " << o.output << "\n";
  return kSuccess;
}

}  // namespace

Action add_patches_command(CLI::App& app) {
  auto o = std::make_shared<PatchesOptions>();
  CLI::App* cmd = app.add_subcommand(
      "patches",
      "Show and edit the boundary patches of a surface (the named sets of faces a solver fixes, loads or heats): "
      "the file's groups (OBJ g/o, ASCII STL solids, a PLY face label) or, when it names none, the regions its "
      "creases bound, named patch_1, patch_2, ... by decreasing area");
  cmd->add_option("input", o->input, "Surface mesh (.off .obj .ply .stl)")->required();
  cmd->add_option("-o,--output", o->output, "The surface with its patches (.ply .obj, or ASCII .stl)");
  add_auto_parameter(*cmd, patch_parameters().feature_angle_deg, o->params.feature_angle_deg);
  add_parameter(*cmd, patch_parameters().resegment, o->params.resegment);
  add_patch_edits(*cmd, o->params);
  cmd->add_option("--json", o->json, "Write the patch table as JSON (- for standard output)");
  return [o] { return run_patches(*o); };
}

}  // namespace meshprep::cli
