#pragma once
/// \file deadline.h
/// The moment a whole command must end by (`--time-limit S`, the Python calls' `time_limit`). A
/// step that has a usable result at any moment (the tet improvement: its best tets so far) takes
/// the time left as its time limit and ends with that result; any other step stops at the
/// deadline with nothing (TimeLimitReached, exit 124).

#include <chrono>
#include <optional>

namespace meshprep {

/// A step's own time limit (ImproveParams, EnhanceParams) set to this: the step's automatic limit,
/// which grows with the mesh (each step states its rule); 0: none.
inline constexpr double kAutomaticTimeLimit = -1;
/// The automatic limits' rules are measured on an optimised build; an instrumented one (CI's
/// sanitizer build, CMakeLists.txt) stretches them by its slowdown, so that its results are a
/// Release build's.
#ifndef MESHPREP_AUTOMATIC_TIME_LIMIT_SCALE
#define MESHPREP_AUTOMATIC_TIME_LIMIT_SCALE 1
#endif
inline constexpr double kAutomaticTimeLimitScale = MESHPREP_AUTOMATIC_TIME_LIMIT_SCALE;

class Deadline {
 public:
  using Clock = std::chrono::steady_clock;

  /// No deadline: never passed, the time left infinite.
  Deadline() = default;
  /// `seconds` from now; 0 (or less) means no deadline.
  static Deadline in_seconds(double seconds);

  bool is_set() const { return end_.has_value(); }
  bool passed() const { return end_ && Clock::now() >= *end_; }
  /// Seconds until the deadline (0 once passed; infinity when there is none).
  double seconds_left() const;
  /// A step's own time limit (0: none) shortened to the time left; once the deadline has passed,
  /// the least positive limit, so that the step stops at its first look at the clock.
  double limit(double own_seconds) const;
  /// A deadline `fraction` of the time left from now (no deadline when this one has none): the
  /// share a step gets when others must still run after it.
  Deadline share(double fraction) const;

 private:
  std::optional<Clock::time_point> end_;
};

}  // namespace meshprep
