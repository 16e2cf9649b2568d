#include "meshprep/core/taken_back.h"

#include <sstream>

namespace meshprep {

std::vector<FigureChange> figure_changes(const TakenBack& taken) {
  std::vector<FigureChange> changes;
  for (const GuardFigure& before : taken.before)
    for (const GuardFigure& after : taken.after)
      if (after.name == before.name) changes.push_back({before.name, before.value, after.value});
  return changes;
}

std::string describe(const TakenBack& taken) {
  std::ostringstream line;
  line << taken.stage << ": ";
  if (taken.count != 1) line << taken.count << ' ';
  line << taken.work << " taken back (" << taken.guard << "): " << taken.reason;
  for (const FigureChange& f : figure_changes(taken)) line << "; " << f.name << ' ' << f.before << " -> " << f.after;
  return line.str();
}

}  // namespace meshprep
