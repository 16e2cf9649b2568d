// Wavefront OBJ reader: `v` and `f` records, and `g` / `o` groups as patches (a face belongs to
// the group named last; of several names on a `g` line, the first); texture, normal, smoothing
// and material records are skipped; free-form geometry is rejected rather than lost. `#` starts
// a comment.
#include "readers.h"
#include "text_scanner.h"

#include <algorithm>
#include <array>

namespace meshprep::detail {
namespace {

// Records that carry no surface geometry.
bool is_ignored_record(std::string_view keyword) {
  static constexpr std::array<std::string_view, 16> ignored = {
      "vt", "vn", "vp", "s", "usemtl", "mtllib", "l", "p", "lod", "bevel", "c_interp", "d_interp", "shadow_obj",
      "trace_obj", "maplib", "usemap"};
  return std::find(ignored.begin(), ignored.end(), keyword) != ignored.end();
}

// The vertex index of a face corner "v", "v/t", "v/t/n" or "v//n"; false if malformed.
bool parse_corner(std::string_view token, std::int64_t& vertex) {
  const std::size_t slash = token.find('/');
  if (!parse_int(token.substr(0, slash), vertex)) return false;
  if (slash == std::string_view::npos) return true;
  const std::string_view rest = token.substr(slash + 1);
  const std::size_t second = rest.find('/');
  const std::string_view texture = rest.substr(0, second);
  std::int64_t ignored = 0;
  if (!texture.empty() && !parse_int(texture, ignored)) return false;
  if (second == std::string_view::npos) return !texture.empty();
  return parse_int(rest.substr(second + 1), ignored);
}

}  // namespace

TriangleSoup read_obj(const std::string& path, std::string_view data, ReadReport& report) {
  report.format = "obj";
  TextScanner in(data, '#');
  const auto fail_here = [&](const std::string& problem) { fail(path, at_line(in.line()) + problem); };

  TriangleSoup soup;
  std::vector<std::uint32_t> corners;
  GroupTags groups;
  int group = 0;  // none named yet
  while (in.seek_token()) {
    const std::string_view keyword = in.token();
    if (keyword == "v") {
      // x y z, then an optional w or r g b that we skip.
      Vec3 p;
      int n_values = 0;
      for (std::string_view token = in.token(); !token.empty(); token = in.token(), ++n_values) {
        double value = 0.0;
        if (!parse_double(token, value)) fail_here("vertex: " + quoted(token) + " is not a number");
        if (n_values < 3) p[n_values] = value;
      }
      if (n_values < 3) fail_here("vertex has " + std::to_string(n_values) + " coordinates, expected 3");
      if (!is_finite(p)) {
        fail_here("vertex " + std::to_string(soup.points.size() + 1) + " has a non-finite coordinate (" +
                  non_finite_text(p) + ")");
      }
      soup.points.push_back(p);
    } else if (keyword == "f") {
      const auto n_vertices = static_cast<std::int64_t>(soup.points.size());
      corners.clear();
      for (std::string_view token = in.token(); !token.empty(); token = in.token()) {
        std::int64_t index = 0;
        if (!parse_corner(token, index)) fail_here("face corner " + quoted(token) + " is not v, v/t, v/t/n or v//n");
        if (index == 0) fail_here("face index 0 is invalid (OBJ indices start at 1)");
        // Positive indices count from 1, negative ones back from the last vertex read.
        const std::int64_t resolved = index > 0 ? index - 1 : n_vertices + index;
        if (resolved < 0 || resolved >= n_vertices) {
          fail_here("face index " + std::to_string(index) + " out of range (" + std::to_string(n_vertices) +
                    " vertices)");
        }
        corners.push_back(static_cast<std::uint32_t>(resolved));
      }
      if (corners.size() < 3) fail_here("face has " + std::to_string(corners.size()) + " corners (at least 3 needed)");
      add_polygon(soup, corners, report, group);
    } else if (keyword == "g" || keyword == "o") {
      const std::string_view name = in.token();
      group = groups.tag(soup, name.empty() ? "default" : std::string(name));
      report.patches_from = "obj groups";
      in.skip_line();
    } else if (is_ignored_record(keyword)) {
      in.skip_line();
    } else {
      fail_here("unsupported record " + quoted(keyword));
    }
  }
  return soup;
}

}  // namespace meshprep::detail
