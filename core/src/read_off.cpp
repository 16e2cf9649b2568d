// OFF reader: "OFF" header (COFF, NOFF, CNOFF and ST prefixes tolerated), counts, vertex lines,
// polygon lines "n i0 ... in-1 [colour]". `#` starts a comment.
#include "readers.h"
#include "text_scanner.h"

#include <limits>

namespace meshprep::detail {
namespace {

enum class OffKind { Plain, WithExtras, NotOff };

// Plain OFF vertex lines hold exactly x y z; the variants append colours, normals or texture
// coordinates, which we skip.
OffKind off_kind(std::string_view keyword) {
  if (keyword == "OFF") return OffKind::Plain;
  for (const std::string_view prefix : {"ST", "C", "N"}) {
    if (keyword.substr(0, prefix.size()) == prefix) keyword.remove_prefix(prefix.size());
  }
  return keyword == "OFF" ? OffKind::WithExtras : OffKind::NotOff;
}

}  // namespace

TriangleSoup read_off(const std::string& path, std::string_view data, ReadReport& report) {
  report.format = "off";
  TextScanner in(data, '#');
  const auto fail_here = [&](const std::string& problem) { fail(path, at_line(in.line()) + problem); };
  // `element` and `index` name the vertex or face for the message ("vertex 12").
  const auto number = [&](std::string_view token, const char* element, std::uint64_t index) {
    double value = 0.0;
    if (!parse_double(token, value)) {
      fail_here(element + std::to_string(index) + ": " + quoted(token) + " is not a number");
    }
    return value;
  };

  if (!in.seek_token()) fail(path, "empty file");
  const std::string_view keyword = in.token();
  const OffKind kind = off_kind(keyword);
  if (kind == OffKind::NotOff) fail_here("expected an OFF header, found " + quoted(keyword));
  if (in.at_line_end() && !in.seek_token()) fail(path, "truncated: no vertex and face counts after the header");

  // Counts "vertices faces [edges]", on the header line or the next one.
  std::int64_t counts[3] = {0, 0, 0};
  int n_counts = 0;
  while (!in.at_line_end()) {
    const std::string_view token = in.token();
    if (token == "BINARY") fail_here("binary OFF is not supported");
    if (n_counts == 3 || !parse_int(token, counts[n_counts]) || counts[n_counts] < 0) {
      fail_here("expected vertex, face and edge counts, found " + quoted(token));
    }
    ++n_counts;
  }
  if (n_counts < 2) fail_here("expected vertex, face and edge counts");
  const auto n_vertices = static_cast<std::uint64_t>(counts[0]);
  const auto n_faces = static_cast<std::uint64_t>(counts[1]);
  if (n_vertices > std::numeric_limits<std::uint32_t>::max()) {
    fail_here("too many vertices (" + std::to_string(n_vertices) + ")");
  }

  TriangleSoup soup;
  soup.points.reserve(capped_count(n_vertices, data.size(), 6));  // "0 0 0\n"
  for (std::uint64_t v = 0; v < n_vertices; ++v) {
    if (!in.seek_token()) {
      fail(path, "truncated: header announces " + std::to_string(n_vertices) + " vertices, found " + std::to_string(v));
    }
    const auto what = [v] { return "vertex " + std::to_string(v); };
    Vec3 p;
    for (int k = 0; k < 3; ++k) {
      const std::string_view token = in.token();
      if (token.empty()) fail_here(what() + " has " + std::to_string(k) + " coordinates, expected 3");
      p[k] = number(token, "vertex ", v);
    }
    if (kind == OffKind::Plain && !in.at_line_end()) {
      fail_here(what() + " has more than 3 values (found " + quoted(in.token()) + "); is the vertex count right?");
    }
    while (!in.at_line_end()) number(in.token(), "vertex ", v);
    if (!is_finite(p)) fail_here(what() + " has a non-finite coordinate (" + non_finite_text(p) + ")");
    soup.points.push_back(p);
  }

  soup.triangles.reserve(capped_count(n_faces, data.size(), 8));  // "3 0 1 2\n"
  std::vector<std::uint32_t> corners;
  for (std::uint64_t f = 0; f < n_faces; ++f) {
    if (!in.seek_token()) {
      fail(path, "truncated: header announces " + std::to_string(n_faces) + " faces, found " + std::to_string(f));
    }
    const auto what = [f] { return "face " + std::to_string(f); };
    const std::string_view count_token = in.token();
    std::int64_t n_corners = 0;
    if (!parse_int(count_token, n_corners)) {
      fail_here(what() + ": expected a corner count, found " + quoted(count_token));
    }
    if (n_corners < 3) fail_here(what() + " has " + std::to_string(n_corners) + " corners (at least 3 needed)");
    corners.clear();
    for (std::int64_t k = 0; k < n_corners; ++k) {
      const std::string_view token = in.token();
      std::int64_t index = 0;
      if (token.empty()) {
        fail_here(what() + " announces " + std::to_string(n_corners) + " corners, found " + std::to_string(k));
      }
      if (!parse_int(token, index)) fail_here(what() + ": " + quoted(token) + " is not a vertex index");
      if (index < 0) fail_here(what() + " has a negative vertex index (" + std::to_string(index) + ")");
      if (static_cast<std::uint64_t>(index) >= n_vertices) {
        fail_here(what() + ": vertex index " + std::to_string(index) + " out of range (" + std::to_string(n_vertices) +
                  " vertices)");
      }
      corners.push_back(static_cast<std::uint32_t>(index));
    }
    // An optional colour: a colour-map index or 3-4 components.
    for (int extra = 0; !in.at_line_end(); ++extra) {
      if (extra == 4) {
        fail_here(what() + " has more values than its " + std::to_string(n_corners) + " corners and a colour");
      }
      number(in.token(), "face ", f);
    }
    add_polygon(soup, corners, report);
  }
  if (in.seek_token()) fail_here("unexpected content after the last face: " + quoted(in.token()));
  return soup;
}

}  // namespace meshprep::detail
