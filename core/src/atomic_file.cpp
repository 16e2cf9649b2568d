// Write-then-rename. The temporary file sits beside the target (rename is only atomic within a
// file system) and keeps its extension, for writers that choose the format from it. Targets that
// are not regular files (/dev/null, a FIFO, /dev/stdout) are written directly: renaming over them
// would replace the device or pipe by a regular file that nobody reads.
#include "meshprep/core/atomic_file.h"

#include "meshprep/core/errors.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace meshprep {
namespace {

namespace fs = std::filesystem;

// Where a write to a path lands, and whether it goes there directly (no temporary, no rename).
struct Destination {
  fs::path path;
  bool direct = false;
};

// /dev/fd/N, /proc/self/fd/N, /proc/<pid>/fd/N: a link that stands for an open descriptor, such as
// the shell's `> file` behind /dev/stdout. Renaming over what it points to would cut that file off
// from the descriptor, so it is written as it is.
bool names_open_descriptor(const fs::path& path) {
  const fs::path folder = path.parent_path();
  if (folder.filename() != "fd") return false;
  const fs::path owner = folder.parent_path();
  return owner == "/dev" || owner.parent_path() == "/proc";
}

// Symlinks are followed (at most 40, as the kernel does), so that a link to a regular file stays a
// link and the file it names is replaced; a path that exists and is not a regular file (a device, a
// FIFO, a socket, a folder) is written directly.
Destination destination_of(const std::string& path) {
  fs::path at(path);
  std::error_code ec;
  for (int hops = 0; hops < 40 && fs::is_symlink(at, ec); ++hops) {
    if (names_open_descriptor(at)) return {at, true};
    const fs::path target = fs::read_symlink(at, ec);
    if (ec) break;
    at = target.is_absolute() ? target : at.parent_path() / target;
  }
  const fs::file_status status = fs::status(at, ec);
  return {at, fs::exists(status) && !fs::is_regular_file(status)};
}

// ".<name>.tmp-<pid>-<counter><extension>" in the directory of `target`.
std::string temporary_path_for(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  const std::string name = "." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                           std::to_string(counter++) + target.extension().string();
  return (target.parent_path() / name).string();
}

// Opens `file` (truncated) and calls `write` on it. \throws WriteError naming `shown` on a stream failure.
void write_stream(const std::string& file, const std::string& shown, const std::function<void(std::ostream&)>& write,
                  bool binary) {
  std::ofstream out(file, binary ? std::ios::out | std::ios::binary : std::ios::out);
  if (!out) throw WriteError(shown + ": cannot write: " + std::strerror(errno));
  try {
    out.exceptions(std::ios::failbit | std::ios::badbit);
    errno = 0;
    write(out);
    out.close();
  } catch (const std::ios_base::failure& failure) {
    // errno still holds the system's reason (e.g. "No space left on device") in practice.
    const std::string reason = errno != 0 ? std::strerror(errno) : failure.what();
    out.exceptions(std::ios::goodbit);
    throw WriteError(shown + ": cannot write: " + reason);
  }
}

void rename_over(const std::string& temporary, const fs::path& target, const std::string& shown) {
  if (std::rename(temporary.c_str(), target.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw WriteError(shown + ": cannot write: " + reason);
  }
}

}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write, bool binary) {
  const Destination destination = destination_of(path);
  if (destination.direct) return write_stream(destination.path.string(), path, write, binary);
  const std::string temporary = temporary_path_for(destination.path);
  try {
    write_stream(temporary, path, write, binary);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  rename_over(temporary, destination.path, path);
}

void write_path_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  const Destination destination = destination_of(path);
  if (destination.direct) return write(destination.path.string());
  const std::string temporary = temporary_path_for(destination.path);
  try {
    write(temporary);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  rename_over(temporary, destination.path, path);
}

}  // namespace meshprep
