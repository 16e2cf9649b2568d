#include "meshprep/fem/solver_targets.h"

#include "meshprep/core/errors.h"

namespace meshprep {

const std::vector<SolverTarget>& solver_targets() {
  static const std::vector<SolverTarget> targets{
      {"mfem", ".msh", {MshVersion::V22, false}},
      {"fenicsx", ".msh", {MshVersion::V41, false}},
      {"dealii", ".msh", {MshVersion::V22, false}},
      {"calculix", ".inp", {}},
      {"code_aster", ".msh", {MshVersion::V22, false}},
  };
  return targets;
}

const SolverTarget& find_solver_target(const std::string& name) {
  std::string valid;
  for (const SolverTarget& t : solver_targets()) {
    if (t.name == name) return t;
    valid += (valid.empty() ? "" : ", ") + t.name;
  }
  throw InvalidInput("unknown solver target '" + name + "' (valid: " + valid + ")");
}

}  // namespace meshprep
