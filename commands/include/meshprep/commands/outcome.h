#pragma once
/// \file outcome.h
/// What a command does, apart from files and the terminal: each command of `meshprep` (simplify,
/// smooth, enhance, repair, reconstruct, quality, tetrahedralize, improve) is one function here
/// taking its input in memory and returning its mesh and the figures its --json writes. The CLI
/// (apps/), the Python module (python/) and the batch are doors onto these functions, so that
/// each gives the same figures for the same input. docs/architecture.md, "Commands".

#include "meshprep/core/deadline.h"
#include "meshprep/core/mesh.h"
#include "meshprep/core/taken_back.h"
#include "meshprep/quality/report.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace meshprep {

/// The caller's hooks into long work: progress in [0, 1] (it may throw Cancelled to stop the
/// work), a cancellation poll (for TetGen and the tet improvement), the name of each long step as
/// it starts ("improving 5210 tets ...") and the whole command's deadline. Any may be empty.
/// `progress` and `cancelled` stop the work for the user (Ctrl-C, a token); the deadline stops
/// only the steps that have nothing usable before they end (until_deadline), while the tet
/// improvement takes the time left as its time limit and ends with its best tets.
struct CommandHooks {
  std::function<void(double)> progress;
  std::function<bool()> cancelled;
  std::function<void(const std::string&)> step;
  Deadline deadline;
  void announce(const std::string& what) const {
    if (step) step(what);
  }
  /// These hooks stopping at the deadline too: progress throws TimeLimitReached, cancelled says
  /// true (the step then throws Cancelled; the caller tells the two apart by deadline.passed()).
  CommandHooks until_deadline() const;
};

/// One line the front end shows the user beside the result: "note: ..." (something changed or
/// skipped that the user should know) or "warning: ..." (the result is weaker than asked).
using CommandMessages = std::vector<std::string>;

/// The names a command's messages and report give its input and its output (file paths on the
/// command line; what the caller calls them elsewhere).
struct CommandNames {
  std::string input, output;
};

/// The notes of the work the guards took back ("note: enhance: remeshing taken back ...").
void add_taken_back_notes(const std::vector<TakenBack>& taken_back, CommandMessages& messages);

/// A surface command's result: the surface made and the command's figures, in the order its
/// --json lists them (the front end adds the file names).
struct SurfaceOutcome {
  TriangleSoup surface;
  nlohmann::ordered_json report = nlohmann::ordered_json::object();
  CommandMessages messages;
};

/// Refuses an output with more self-intersecting face pairs than its input had: \throws SolverError
/// "INPUT: the WHAT surface intersects itself at N more face pairs than the input (first: faces a
/// and b); nothing written. ADVICE". When it has as many or fewer but some, a warning says so.
void refuse_new_intersections(const QualityReport& output, std::size_t input_intersections, const CommandNames& names,
                              const std::string& what, const std::string& advice, CommandMessages& messages);

}  // namespace meshprep
