#pragma once
/// \file taken_back.h
/// Work a stage did and then took back because a guard found it made the mesh worse: a remeshing
/// that made the surface cross itself, vertex moves that folded a face, a tet improvement's detour
/// that ended lower than it began. Each stage's Result lists them; every report shows them under
/// the one key `guards_taken_back` (json_values.h), so that nothing is undone without a word.

#include <cstddef>
#include <string>
#include <vector>

namespace meshprep {

/// A named figure the guard compared (a count, a fraction, an angle).
struct GuardFigure {
  std::string name;
  double value = 0;
};

struct TakenBack {
  std::string stage;   ///< the stage that took its work back: "enhance", "smooth", ...
  std::string guard;   ///< what decided: "self-intersection", "face limit", "no gain", ...
  std::string work;    ///< what was taken back: "remeshing", "vertex moves", ...
  std::size_t count = 1;  ///< how many of them (moves, rounds, restarts)
  std::string reason;  ///< one sentence, naming what was kept instead
  /// The figures before the guard acted (as the work left the mesh) and after (as it is kept).
  std::vector<GuardFigure> before, after;
};

/// A figure present both before and after: "name before -> after" in the reports.
struct FigureChange {
  std::string name;
  double before = 0, after = 0;
};

/// The figures of `taken` that are both in `before` and `after`, in `before`'s order.
std::vector<FigureChange> figure_changes(const TakenBack& taken);

/// One line for a terminal: "enhance: remeshing taken back (self-intersection): <reason>;
/// faces 5210 -> 1280; ...", each figure as the work left it -> as it is kept.
std::string describe(const TakenBack& taken);

}  // namespace meshprep
