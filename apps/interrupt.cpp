#include "interrupt.h"

#include "meshprep/core/errors.h"

#include <csignal>

namespace meshprep::cli {
namespace {

volatile std::sig_atomic_t stop_flag = 0;
volatile std::sig_atomic_t stop_signal_number = 0;
Deadline deadline;

void on_stop_signal(int signal_number) {
  if (stop_flag) {  // the second Ctrl-C (or SIGTERM): the sender insists
    std::signal(signal_number, SIG_DFL);
    std::raise(signal_number);
    return;
  }
  stop_signal_number = signal_number;
  stop_flag = 1;
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) sigaction(signal_number, &action, nullptr);
}

void set_time_limit(double seconds) { deadline = Deadline::in_seconds(seconds); }

const Deadline& time_limit() { return deadline; }

bool stop_requested() { return stop_flag != 0; }

int stopped_exit_code() { return 128 + (stop_signal_number != 0 ? stop_signal_number : SIGINT); }

std::string stop_reason() {
  if (stop_signal_number == SIGTERM) return "terminated (SIGTERM)";
  if (stop_signal_number == SIGHUP) return "hung up (SIGHUP)";
  return "interrupted";
}

void throw_if_stop_requested() {
  if (stop_requested()) throw Cancelled(stop_reason() + "; nothing written");
}

std::function<void(double)> stoppable(std::function<void(double)> draw) {
  return [draw = std::move(draw)](double fraction) {
    draw(fraction);
    throw_if_stop_requested();
  };
}

}  // namespace meshprep::cli
