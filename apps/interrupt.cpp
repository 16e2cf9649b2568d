#include "interrupt.h"

#include "meshprep/core/errors.h"

#include <unistd.h>

#include <csignal>

namespace meshprep::cli {
namespace {

volatile std::sig_atomic_t stop_flag = 0;
volatile std::sig_atomic_t timeout_flag = 0;

void on_interrupt(int) {
  if (stop_flag) {  // the second Ctrl-C: the user insists
    std::signal(SIGINT, SIG_DFL);
    std::raise(SIGINT);
    return;
  }
  stop_flag = 1;
}

void on_alarm(int) {
  timeout_flag = 1;
  stop_flag = 1;
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  action.sa_handler = on_alarm;
  sigaction(SIGALRM, &action, nullptr);
}

void arm_timeout(unsigned seconds) { ::alarm(seconds); }

bool stop_requested() { return stop_flag != 0; }

bool timed_out() { return timeout_flag != 0; }

void throw_if_stop_requested() {
  if (stop_requested()) throw Cancelled(timed_out() ? "timed out; nothing written" : "interrupted; nothing written");
}

std::function<void(double)> stoppable(std::function<void(double)> draw) {
  return [draw = std::move(draw)](double fraction) {
    draw(fraction);
    throw_if_stop_requested();
  };
}

}  // namespace meshprep::cli
