#include "tet_second_order.h"

#include "cli_common.h"
#include "cli_parameters.h"

#include "meshprep/fem/fem_parameters.h"
#include "meshprep/fem/tet_boundary.h"
#include "meshprep/report/number_format.h"

#include <unistd.h>

#include <iostream>

namespace meshprep::cli {

CLI::Option* add_order_option(CLI::App& cmd, ElementOrderParams& params) {
  return add_parameter(cmd, element_order_parameters().order, params.order);
}

CLI::Option* add_reference_option(CLI::App& cmd, std::string& path) {
  return cmd.add_option("--reference", path,
                        "With --order 2: the surface (.off .obj .ply .stl) the boundary's mid-edge nodes go onto "
                        "(default: the tets' own boundary, which leaves them straight)");
}

QuadraticResult make_second_order(TetMesh& tets, const TriangleSoup* reference, nlohmann::ordered_json& json) {
  if (::isatty(STDERR_FILENO))
    std::cerr << "meshprep: making " << tets.tets.size() << " tets second-order (10 nodes) ...\n";
  const TriangleSoup own_boundary = reference ? TriangleSoup{} : boundary_surface(tets);
  const QuadraticResult result = make_quadratic(tets, reference ? reference : &own_boundary);
  json["second_order"] = to_json(result);
  note_taken_back(result.taken_back);
  return result;
}

std::string second_order_summary(const QuadraticResult& r) {
  const std::size_t straight = r.straight_inverting + r.straight_off_reference;
  return std::to_string(r.curved_edges) + " of " + std::to_string(r.boundary_edges) + " boundary edges curved, " +
         std::to_string(r.on_reference) + " on the surface already, " + std::to_string(straight) + " left straight (" + std::to_string(r.straight_inverting) + " would fold a tet, " +
         std::to_string(r.straight_off_reference) + " off the surface), smallest scaled Jacobian " +
         format_number(r.min_scaled_jacobian, 3);
}

}  // namespace meshprep::cli
