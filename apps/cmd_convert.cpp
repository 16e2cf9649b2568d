// meshprep convert IN OUT [--binary]: between the surface formats, without changing the mesh.
#include "cli_common.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"

#include <iostream>
#include <memory>

namespace meshprep::cli {

Action add_convert_command(CLI::App& app) {
  struct Options {
    std::string input, output;
    bool binary = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("convert", "Convert a surface mesh between OFF, OBJ, PLY and STL (format from the extension)");
  cmd->add_option("input", o->input, "Input surface mesh")->required();
  cmd->add_option("output", o->output, "Output surface mesh")->required();
  cmd->add_flag("--binary", o->binary, "Binary PLY/STL instead of ASCII");
  return [o] {
    ensure_not_input(o->output, o->input);
    ReadReport read;
    const TriangleSoup soup = read_soup(o->input, &read);
    WriteOptions options;
    options.binary = o->binary;
    try {
      write_soup(soup, o->output, options);
    } catch (const InvalidInput& e) {  // the format cannot hold this input: name both
      throw InvalidInput(o->input + " -> " + e.what());
    }
    std::cout << o->input << " -> " << o->output << ": " << soup.points.size() << " vertices, " << soup.triangles.size()
              << " triangles";
    if (read.polygons_triangulated > 0) std::cout << " (" << read.polygons_triangulated << " polygons triangulated)";
    std::cout << '\n';
    return kSuccess;
  };
}

}  // namespace meshprep::cli
