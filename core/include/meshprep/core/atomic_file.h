#pragma once
/// \file atomic_file.h
/// Write-then-rename: the target path only ever holds a complete file (or its previous content).

#include <functional>
#include <ostream>
#include <string>

namespace meshprep {

/// Calls `write` with a stream on a temporary file in the target's directory, then renames it
/// over `path`. If `write` throws, or the stream fails, the temporary file is removed, `path` is
/// untouched, and an exception is thrown (IoError for stream failures, else the original one).
/// `binary` opens the stream in binary mode.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary = false);

/// Same, for writers that need a path (e.g. a third-party writer): `write` receives the temporary
/// file's path, which has the same extension as `path`.
void write_path_atomically(const std::string& path, const std::function<void(const std::string&)>& write);

}  // namespace meshprep
