#pragma once
/// \file fem_verdict.h
/// Are the tets good enough for a finite-element solve? Explicit thresholds on their quality,
/// each judged against its figure, so that "FEM-ready" is a claim a report can back line by line.
///
/// The defaults hold what linear tets need (J. R. Shewchuk, "What Is a Good Linear Finite
/// Element?", 2002): a small dihedral angle makes the stiffness matrix ill-conditioned (its
/// condition number grows like 1 / sin of the smallest angle), a large one spoils the gradient
/// of the interpolant (the error grows like 1 / sin of the largest), an inverted tet has a
/// negative Jacobian no solver accepts.

#include "meshprep/fem/tet_quality.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace meshprep {

/// The thresholds of the verdict; the pipeline's `verdict` section and the CLI's threshold flags
/// take their defaults from here.
struct TetThresholds {
  /// The smallest dihedral angle allowed, degrees, in [0, 180] (0: any). 10 is where FEM codes
  /// commonly start warning; the regular tet has 70.53.
  double min_dihedral_deg = 10;
  /// The largest dihedral angle allowed, degrees, in [0, 180] (180: any).
  double max_dihedral_deg = 165;
  /// How many inverted or flat tets (volume <= 0) are allowed: none. For a second-order mesh, the
  /// tets with det J <= 0 at one of their ten nodes count too (QuadraticTetQuality).
  std::size_t max_inverted_tets = 0;
};

/// One threshold beside the tets' figure.
struct ThresholdCheck {
  std::string check;   ///< the threshold's name: min_dihedral_deg, max_dihedral_deg or max_inverted_tets
  double threshold = 0;
  double value = 0;    ///< the tets' figure; NaN when there are no tets (then the check fails)
  bool ok = false;
};

/// Every threshold's check, in the order of TetThresholds' fields.
struct TetVerdict {
  std::vector<ThresholdCheck> checks;
  bool ok() const;                           ///< every check holds
  std::vector<ThresholdCheck> failed() const;  ///< the checks that do not hold, in order
};

/// \throws InvalidInput "verdict: <field> must be in [0, 180], not <value>" for an angle outside
/// [0, 180] or NaN (a NaN threshold would fail every mesh, or with >= pass none).
void check_thresholds(const TetThresholds& thresholds);

/// Judge `report` against `thresholds` (checked: check_thresholds): the smallest dihedral angle must be >= min_dihedral_deg,
/// the largest <= max_dihedral_deg, the inverted tets <= max_inverted_tets. An empty mesh fails
/// the angle checks (there is nothing to solve on).
TetVerdict judge_tets(const TetQualityReport& report, const TetThresholds& thresholds = {});

/// The threshold as a requirement: "smallest dihedral angle >= 10 deg".
std::string requirement(const ThresholdCheck& check);

/// One line for a person: "smallest dihedral angle 0.78 deg < 10 deg (min_dihedral_deg)" when the
/// check fails, "... >= 10 deg ..." when it holds.
std::string describe(const ThresholdCheck& check);

/// {"check": "min_dihedral_deg", "threshold": 10, "value": 0.78, "ok": false} (value null when NaN).
nlohmann::ordered_json to_json(const ThresholdCheck& check);

/// The checks as a JSON array.
nlohmann::ordered_json to_json(const TetVerdict& verdict);

}  // namespace meshprep
