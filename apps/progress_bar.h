#pragma once
// A one-line progress bar with an ETA on stderr when stderr is a terminal; elsewhere (a log file, a
// batch's pipe) one line every kLineInterval while the work lasts, so that a long run is seen to move.

#include <chrono>
#include <string>

namespace meshprep::cli {

class ProgressBar {
 public:
  explicit ProgressBar(std::string label);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// Redraw for `fraction` in [0, 1] (at most ten times a second on a terminal).
  void update(double fraction);
  /// Redraw with the last fraction: the clock moves while a step without progress (TetGen) runs.
  void tick() { update(fraction_); }
  /// Erase the bar.
  void finish();

  /// Off a terminal: a line no more often than this.
  static constexpr std::chrono::seconds kLineInterval{5};

 private:
  std::string label_;
  bool terminal_, active_ = true;
  double fraction_ = 0;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace meshprep::cli
