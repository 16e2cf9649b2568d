// read_input_file: the whole content of an input, which must be a regular file.
#include "meshprep/core/io.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/unique_fd.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace meshprep {
namespace {

// What a file that is not a regular one is, for the message that refuses it.
std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  return "a special file";
}

}  // namespace

std::string read_input_file(const std::string& path) {
  // O_NONBLOCK: a FIFO without a writer opens at once (to be refused below) instead of blocking
  // in open(); it changes nothing for a regular file.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw IoError(path + ": cannot open: " + std::strerror(errno));
  const UniqueFd closes(fd);
  struct stat info {};
  if (::fstat(fd, &info) != 0) throw IoError(path + ": cannot read: " + std::strerror(errno));
  // A device or a pipe may never end (/dev/zero) or never start (a FIFO nobody writes to).
  if (!S_ISREG(info.st_mode))
    throw InvalidInput(path + ": not a regular file (" + kind_of(info.st_mode) +
                       "): meshprep reads its input from files only");
  std::string data;
  data.reserve(static_cast<std::size_t>(std::max<off_t>(info.st_size, 0)));
  char chunk[1 << 16];
  for (;;) {
    const ssize_t got = ::read(fd, chunk, sizeof chunk);
    if (got == 0) return data;
    if (got < 0 && errno != EINTR) throw IoError(path + ": cannot read: " + std::strerror(errno));
    if (got > 0) data.append(chunk, static_cast<std::size_t>(got));
  }
}

}  // namespace meshprep
