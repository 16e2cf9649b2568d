#pragma once
/// \file atomic_file.h
/// Write-then-rename: the target path only ever holds a complete file (or its previous content).
///
/// What the target is decides how it is written:
/// - a regular file, or nothing yet: a temporary file beside it, renamed over it;
/// - a symlink: followed; the file it leads to is replaced as above, and the link stays a link
///   (never replaced by a regular file);
/// - an existing file that is not regular (/dev/null, /dev/full, a FIFO, a socket) and a path that
///   names an open descriptor (/dev/stdout, /dev/fd/N, /proc/self/fd/N): written directly, without
///   a temporary (a rename would replace the device or pipe by a file nobody reads). Such a write
///   is not atomic: a failure may leave part of it with the reader.

#include <functional>
#include <ostream>
#include <string>

namespace meshprep {

/// Calls `write` with a stream on a temporary file in the target's directory, then renames it
/// over `path`. If `write` throws, or the stream fails, the temporary file is removed, `path` is
/// untouched, and an exception is thrown (WriteError for stream failures, else the original one).
/// `binary` opens the stream in binary mode.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary = false);

/// Same, for writers that need a path (e.g. a third-party writer): `write` receives the temporary
/// file's path, which has the same extension as `path`.
void write_path_atomically(const std::string& path, const std::function<void(const std::string&)>& write);

}  // namespace meshprep
