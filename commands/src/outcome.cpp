#include "meshprep/commands/outcome.h"

#include "meshprep/core/errors.h"

namespace meshprep {

CommandHooks CommandHooks::until_deadline() const {
  if (!deadline.is_set()) return *this;
  CommandHooks bounded = *this;
  bounded.progress = [progress = progress, deadline = deadline](double fraction) {
    if (deadline.passed()) throw TimeLimitReached("time limit reached");
    if (progress) progress(fraction);
  };
  bounded.cancelled = [cancelled = cancelled, deadline = deadline] {
    return deadline.passed() || (cancelled && cancelled());
  };
  return bounded;
}

void add_taken_back_notes(const std::vector<TakenBack>& taken_back, CommandMessages& messages) {
  for (const TakenBack& t : taken_back) messages.push_back("note: " + describe(t));
}

void refuse_new_intersections(const QualityReport& output, std::size_t input_intersections, const CommandNames& names,
                              const std::string& what, const std::string& advice, CommandMessages& messages) {
  if (output.self_intersections > 0 && output.self_intersections <= input_intersections) {
    messages.push_back("warning: " + names.output + " still intersects itself at " + std::to_string(output.self_intersections) +
                       " face pairs (the input at " + std::to_string(input_intersections) + "): tets need a surface that does not");
    return;
  }
  const std::size_t new_pairs = new_self_intersections(output, input_intersections);
  if (new_pairs == 0) return;
  throw SolverError(names.input + ": the " + what + " surface intersects itself at " + std::to_string(new_pairs) +
                    " more face pairs than the input (first: faces " +
                    std::to_string(output.self_intersecting_pairs.front().first) + " and " +
                    std::to_string(output.self_intersecting_pairs.front().second) + "); nothing written. " + advice);
}

}  // namespace meshprep
