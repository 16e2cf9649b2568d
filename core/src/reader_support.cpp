#include "readers.h"

#include "meshprep/core/errors.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

namespace meshprep::detail {

std::string read_file(const std::string& path) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw IoError(path + ": cannot open: " + std::strerror(errno));
  std::string data;
  struct stat info {};
  if (::fstat(::fileno(file.get()), &info) == 0 && info.st_size > 0) {
    data.reserve(static_cast<std::size_t>(info.st_size));
  }
  char chunk[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(chunk, 1, sizeof chunk, file.get())) > 0) data.append(chunk, got);
  if (std::ferror(file.get())) throw IoError(path + ": cannot read: " + std::strerror(errno));
  return data;
}

void fail(const std::string& path, const std::string& problem) { throw InvalidInput(path + ": " + problem); }

std::string unknown_extension_problem(const std::string& extension) {
  const std::string supported = " (supported: .off, .obj, .ply, .stl)";
  if (extension.empty()) return "no file extension to choose the format from" + supported;
  return "unknown mesh extension '." + extension + "'" + supported;
}

std::string at_line(std::size_t line) { return "line " + std::to_string(line) + ": "; }

bool is_finite(const Vec3& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

std::string non_finite_text(const Vec3& p) {
  for (int i = 0; i < 3; ++i) {
    if (std::isnan(p[i])) return "nan";
    if (std::isinf(p[i])) return p[i] > 0 ? "inf" : "-inf";
  }
  return "finite";
}

std::size_t capped_count(std::uint64_t announced, std::size_t bytes, std::size_t min_bytes_each) {
  return static_cast<std::size_t>(std::min<std::uint64_t>(announced, bytes / std::max<std::size_t>(min_bytes_each, 1)));
}

void add_polygon(TriangleSoup& soup, const std::vector<std::uint32_t>& corners, ReadReport& report) {
  ++report.faces_in_file;
  if (corners.size() > 3) ++report.polygons_triangulated;
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
    soup.triangles.push_back({corners[0], corners[i], corners[i + 1]});
  }
}

}  // namespace meshprep::detail
