#pragma once
// A one-line progress bar with an ETA on stderr, drawn only when stderr is a terminal.

#include <chrono>
#include <string>

namespace meshprep::cli {

class ProgressBar {
 public:
  explicit ProgressBar(std::string label);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// Redraw for `fraction` in [0, 1] (at most ten times a second).
  void update(double fraction);
  /// Erase the bar.
  void finish();

 private:
  std::string label_;
  bool active_;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace meshprep::cli
