#include "tet_second_order.h"

#include "cli_parameters.h"

#include "meshprep/fem/fem_parameters.h"

namespace meshprep::cli {

CLI::Option* add_order_option(CLI::App& cmd, ElementOrderParams& params) {
  return add_parameter(cmd, element_order_parameters().order, params.order);
}

CLI::Option* add_reference_option(CLI::App& cmd, std::string& path) {
  return cmd.add_option("--reference", path,
                        "With --order 2: the surface (.off .obj .ply .stl) the boundary's mid-edge nodes go onto "
                        "(default: the tets' own boundary, which leaves them straight)");
}

}  // namespace meshprep::cli
