#include "isolated_call.h"

#include "meshprep/core/errors.h"

#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>

#include <cerrno>
#include <cstring>

namespace meshprep::detail {
namespace {

void write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent went away: nothing to report to
    done += static_cast<std::size_t>(n);
  }
}

int wait_for(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

}  // namespace

IsolatedResult call_isolated(const std::function<std::string()>& work, const std::function<bool()>& cancelled) {
  int fds[2];
  if (::pipe(fds) != 0) throw IoError(std::string("cannot create a pipe: ") + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw IoError(std::string("cannot fork: ") + std::strerror(errno));
  }
  if (pid == 0) {  // child: do the work, send the bytes, leave without running atexit handlers
    // Ctrl-C is the parent's to handle (it kills the child through `cancelled`), and the child
    // must not outlive a parent that is killed.
    std::signal(SIGINT, SIG_IGN);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    ::close(fds[0]);
    std::string output;
    try {
      output = work();
    } catch (...) {
      ::_exit(3);
    }
    write_all(fds[1], output);
    ::close(fds[1]);
    ::_exit(0);
  }
  ::close(fds[1]);
  IsolatedResult result;
  char buffer[1 << 16];
  constexpr int kPollMilliseconds = 50;
  for (;;) {
    if (cancelled && cancelled()) {
      ::kill(pid, SIGKILL);
      ::close(fds[0]);
      wait_for(pid);
      throw Cancelled("stopped while the child process was working");
    }
    pollfd readable{fds[0], POLLIN, 0};
    const int ready = ::poll(&readable, 1, cancelled ? kPollMilliseconds : -1);
    if (ready == 0 || (ready < 0 && errno == EINTR)) continue;
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    result.output.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  const int status = wait_for(pid);
  if (WIFSIGNALED(status)) {
    result.crashed = true;
    result.signal = WTERMSIG(status);
  } else {
    result.exit_status = WEXITSTATUS(status);
    result.crashed = result.exit_status != 0;
  }
  return result;
}

}  // namespace meshprep::detail
