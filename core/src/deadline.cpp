#include "meshprep/core/deadline.h"

#include <algorithm>
#include <limits>

namespace meshprep {

Deadline Deadline::in_seconds(double seconds) {
  Deadline deadline;
  if (seconds > 0)
    deadline.end_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  return deadline;
}

double Deadline::seconds_left() const {
  if (!end_) return std::numeric_limits<double>::infinity();
  return std::max(0.0, std::chrono::duration<double>(*end_ - Clock::now()).count());
}

double Deadline::limit(double own_seconds) const {
  if (!end_) return own_seconds;
  const double left = std::max(seconds_left(), std::numeric_limits<double>::min());
  return own_seconds > 0 ? std::min(own_seconds, left) : left;
}

Deadline Deadline::share(double fraction) const {
  if (!end_) return {};
  return in_seconds(std::max(fraction * seconds_left(), std::numeric_limits<double>::min()));
}

}  // namespace meshprep
