#pragma once
// The flags of second-order tets (tetrahedralize, improve, convert, --order 2); commands/'s
// make_second_order makes them.

#include "meshprep/fem/quadratic.h"

#include <CLI/CLI.hpp>

#include <string>

namespace meshprep::cli {

/// --order 1|2 (fem_parameters.h), bound to `params`, its default shown.
CLI::Option* add_order_option(CLI::App& cmd, ElementOrderParams& params);

/// --reference SURFACE: the surface a second-order mesh's boundary nodes go onto, for commands
/// whose input is a tet mesh (improve, convert); bound to `path`.
CLI::Option* add_reference_option(CLI::App& cmd, std::string& path);

}  // namespace meshprep::cli
