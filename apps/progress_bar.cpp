#include "progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace meshprep::cli {

ProgressBar::ProgressBar(std::string label)
    : label_(std::move(label)), terminal_(::isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()),
      last_draw_(terminal_ ? start_ - std::chrono::seconds(1) : start_) {}  // a terminal's first update draws at once

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::update(double fraction) {
  if (!active_) return;
  fraction_ = fraction = std::clamp(fraction, 0.0, 1.0);
  const auto now = std::chrono::steady_clock::now();
  if (now - last_draw_ < (terminal_ ? std::chrono::steady_clock::duration(std::chrono::milliseconds(100)) : kLineInterval))
    return;
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (!terminal_) {
    std::fprintf(stderr, "meshprep: %s: %.0f%% after %.0f s\n", label_.c_str(), 100 * fraction, elapsed);
    std::fflush(stderr);
    return;
  }
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(std::lround(fraction * kWidth));
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(kWidth, '.');
  if (fraction > 0.02)
    std::fprintf(stderr, "\r%s [%s] %3.0f%%  ETA %.0f s ", label_.c_str(), bar.c_str(), 100 * fraction,
                 elapsed * (1 - fraction) / fraction);
  else
    std::fprintf(stderr, "\r%s [%s] %3.0f%%           ", label_.c_str(), bar.c_str(), 100 * fraction);
  std::fflush(stderr);
}

void ProgressBar::finish() {
  if (!active_) return;
  active_ = false;
  if (!terminal_) return;
  std::fprintf(stderr, "\r%*s\r", static_cast<int>(label_.size()) + 60, "");
  std::fflush(stderr);
}

}  // namespace meshprep::cli
