#pragma once
// Second-order tets as the commands make them (tetrahedralize, improve, convert, --order 2): the
// flag, make_quadratic on the final linear tets, its figures in the command's JSON and a line.

#include "meshprep/core/mesh.h"
#include "meshprep/fem/quadratic.h"
#include "meshprep/fem/tet_mesh.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace meshprep::cli {

/// --order 1|2 (fem_parameters.h), bound to `params`, its default shown.
CLI::Option* add_order_option(CLI::App& cmd, ElementOrderParams& params);

/// --reference SURFACE: the surface a second-order mesh's boundary nodes go onto, for commands
/// whose input is a tet mesh (improve, convert); bound to `path`.
CLI::Option* add_reference_option(CLI::App& cmd, std::string& path);

/// Makes linear `tets` second-order (make_quadratic) onto `reference`, or onto the tets' own
/// boundary when it is null (then every boundary node stays on its flat face).
/// json["second_order"] = the figures (quadratic.h's to_json); a line on stderr on a terminal.
QuadraticResult make_second_order(TetMesh& tets, const TriangleSoup* reference, nlohmann::ordered_json& json);

/// "1234 of 2000 boundary edges curved, 761 on the surface already, 5 left straight (3 would fold a tet, 2 off the surface), smallest
/// scaled Jacobian 0.41".
std::string second_order_summary(const QuadraticResult& result);

}  // namespace meshprep::cli
