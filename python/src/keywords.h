#pragma once
// A Python function's keywords are the configuration file's keys (pipeline_config.h): its own
// section's keys given flat (simplify(surface, ratio=0.1)), other sections as dicts of their keys
// (tetrahedralize(surface, verdict={"min_dihedral_deg": 12}), or True/False for their "enabled").
// They are applied by the same key table as the file, so names, types and ranges have one home,
// and checked before any work.

#include "meshprep/pipeline/pipeline_config.h"

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace meshprep::python {

namespace py = pybind11;

struct Keywords {
  std::string function;               ///< "simplify", as messages name the call: "meshprep.simplify()"
  std::string own;                    ///< the section whose keys are flat keywords ("" for none)
  std::vector<std::string> sections;  ///< sections taken as dict keywords
  std::vector<std::string> refused;   ///< keys of `own` that do not apply to this function
};

/// A Python value (bool, int, float, str, None, list, tuple, dict, numpy scalar) as JSON.
/// \throws InvalidInput for anything else.
nlohmann::json json_value(const py::handle& value, const std::string& what);

/// Applies `kwargs` onto `config` as `spec` says. \throws InvalidInput naming the keyword and what
/// it takes (an unknown keyword lists the valid ones).
void apply_keywords(const Keywords& spec, const py::dict& kwargs, PipelineConfig& config);

/// The keywords of `spec` as a docstring: one line per key with its type, its default in `config`
/// and its meaning.
std::string keyword_doc(const Keywords& spec, const PipelineConfig& config);

}  // namespace meshprep::python
