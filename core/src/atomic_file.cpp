// Write-then-rename. The temporary file sits beside the target (rename is only atomic within a
// file system) and keeps its extension, for writers that choose the format from it.
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

// ".<name>.tmp-<pid>-<counter><extension>" in the directory of `path`.
std::string temporary_path_for(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path target(path);
  const std::string name = "." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                           std::to_string(counter++) + target.extension().string();
  return (target.parent_path() / name).string();
}

void rename_over(const std::string& temporary, const std::string& path) {
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw IoError(path + ": cannot write: " + reason);
  }
}

}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write, bool binary) {
  const std::string temporary = temporary_path_for(path);
  std::ofstream out(temporary, binary ? std::ios::out | std::ios::binary : std::ios::out);
  if (!out) throw IoError(path + ": cannot write: " + std::strerror(errno));
  try {
    out.exceptions(std::ios::failbit | std::ios::badbit);
    errno = 0;
    write(out);
    out.close();
  } catch (const std::ios_base::failure& failure) {
    // errno still holds the system's reason (e.g. "No space left on device") in practice.
    const std::string reason = errno != 0 ? std::strerror(errno) : failure.what();
    out.exceptions(std::ios::goodbit);
    out.close();
    std::remove(temporary.c_str());
    throw IoError(path + ": cannot write: " + reason);
  } catch (...) {
    out.exceptions(std::ios::goodbit);
    out.close();
    std::remove(temporary.c_str());
    throw;
  }
  rename_over(temporary, path);
}

void write_path_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  const std::string temporary = temporary_path_for(path);
  try {
    write(temporary);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  rename_over(temporary, path);
}

}  // namespace meshprep
