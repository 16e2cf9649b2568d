#pragma once
/// \file unique_fd.h
/// A POSIX file descriptor closed (and so any flock on it released) when its owner goes away.

#include <unistd.h>

namespace meshprep {

class UniqueFd {
 public:
  /// Owns `fd`; a negative value (a failed open) owns nothing.
  explicit UniqueFd(int fd = -1) : fd_(fd) {}
  ~UniqueFd() {
    if (fd_ >= 0) ::close(fd_);
  }
  UniqueFd(const UniqueFd&) = delete;
  UniqueFd& operator=(const UniqueFd&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

}  // namespace meshprep
