#include "meshprep/core/taken_back.h"

#include <sstream>

namespace meshprep {

std::string describe(const TakenBack& taken) {
  std::ostringstream line;
  line << taken.stage << ": ";
  if (taken.count != 1) line << taken.count << ' ';
  line << taken.work << " taken back (" << taken.guard << "): " << taken.reason;
  // The figures in pairs: a name present before and after reads "name a -> b".
  for (const GuardFigure& before : taken.before)
    for (const GuardFigure& after : taken.after)
      if (after.name == before.name) line << "; " << before.name << ' ' << before.value << " -> " << after.value;
  return line.str();
}

}  // namespace meshprep
