// XYZ point reader: "x y z" or "x y z nx ny nz" per line, the same on every line; `#` comments.
#include "meshprep/core/io.h"

#include "readers.h"
#include "text_scanner.h"

#include <cmath>

namespace meshprep {

PointSet detail::parse_points(const std::string& path, std::string_view data) {
  if (data.empty()) fail(path, "empty file");
  TextScanner in(data, '#');
  const auto fail_here = [&](const std::string& problem) { fail(path, at_line(in.line()) + problem); };

  PointSet set;
  set.points.reserve(capped_count(data.size(), data.size(), 12));  // "0 0 0\n" at best, usually more
  std::size_t columns = 0;                                         // of the first line
  std::size_t first_line = 0;
  while (in.seek_token()) {
    double values[6];
    std::size_t n = 0;
    for (std::string_view token = in.token(); !token.empty(); token = in.token(), ++n) {
      if (n == 6) fail_here("more than 6 values (expected x y z or x y z nx ny nz)");
      if (!parse_double(token, values[n])) fail_here(quoted(token) + " is not a number");
      if (!std::isfinite(values[n])) fail_here("non-finite value " + quoted(token));
    }
    if (n != 3 && n != 6) fail_here(std::to_string(n) + " values (expected x y z or x y z nx ny nz)");
    if (columns == 0) {
      columns = n;
      first_line = in.line();
    } else if (n != columns) {
      fail_here(std::to_string(n) + " values, but line " + std::to_string(first_line) + " has " +
                std::to_string(columns) + " (3- and 6-column lines mixed)");
    }
    set.points.emplace_back(values[0], values[1], values[2]);
    if (n == 6) set.normals.emplace_back(values[3], values[4], values[5]);
  }
  if (set.points.empty()) fail(path, "no points");
  check_extent(path, set.points);
  return set;
}

PointSet read_points(const std::string& path) {
  detail::refuse_folder(path);
  if (is_surface_mesh_path(path))
    detail::fail(path, "a surface mesh (." + extension_of(path) + "), not a point set (.xyz: x y z per line)");
  return detail::parse_points(path, read_input_file(path));
}

}  // namespace meshprep
