// STL reader, ASCII and binary. A file is binary when its size is exactly 84 + 50 n bytes for the
// triangle count n stored at byte 80, even if its header starts with "solid" (many exporters
// write such headers); otherwise it must be ASCII text. STL stores each corner separately: corners with
// exactly equal coordinates become one soup vertex. The solids of an ASCII file are its patches,
// named by their `solid` lines ("solid_<k>" for a solid without a name).
#include "byte_order.h"
#include "readers.h"
#include "text_scanner.h"

#include <array>
#include <cctype>
#include <cstring>
#include <unordered_map>

namespace meshprep::detail {
namespace {

constexpr std::size_t header_bytes = 80;
constexpr std::size_t triangle_bytes = 50;  // normal, 3 corners (float32 each), attribute uint16

// Soup vertices by exact coordinates.
class CornerMerger {
 public:
  CornerMerger(TriangleSoup& soup, std::size_t expected_vertices) : soup_(soup) { index_.reserve(expected_vertices); }

  std::uint32_t index_of(const Vec3& p) {
    // +0.0 makes -0.0 and 0.0, which compare equal, one key.
    const Key key = {p.x() + 0.0, p.y() + 0.0, p.z() + 0.0};
    const auto [it, added] = index_.try_emplace(key, static_cast<std::uint32_t>(soup_.points.size()));
    if (added) soup_.points.push_back(p);
    return it->second;
  }

 private:
  using Key = std::array<double, 3>;
  struct KeyHash {
    std::size_t operator()(const Key& key) const {
      std::size_t hash = 0;
      for (const double c : key) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &c, sizeof bits);
        hash = (hash ^ bits) * 0x100000001b3ull;
        hash ^= hash >> 29;
      }
      return hash;
    }
  };

  TriangleSoup& soup_;
  std::unordered_map<Key, std::uint32_t, KeyHash> index_;
};

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  if (a == b) return true;  // the usual lower-case keywords, fast
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  }
  return true;
}

// ASCII STL starts with "solid" and, unlike binary STL (counts, attributes), has no NUL byte.
bool looks_like_ascii(std::string_view data) {
  TextScanner in(data);
  return in.seek_token() && equals_ignoring_case(in.token(), "solid") && data.find('\0') == std::string_view::npos;
}

TriangleSoup read_binary(const std::string& path, std::string_view data, std::uint32_t n_triangles,
                         ReadReport& report) {
  report.format = "stl-binary";
  TriangleSoup soup;
  soup.triangles.reserve(n_triangles);
  CornerMerger merger(soup, n_triangles / 2 + 3);  // a closed mesh has about half as many vertices
  std::vector<std::uint32_t> corners(3);
  for (std::uint32_t t = 0; t < n_triangles; ++t) {
    const char* corner = data.data() + header_bytes + 4 + std::size_t{t} * triangle_bytes + 12;  // after the normal
    for (int c = 0; c < 3; ++c, corner += 12) {
      const Vec3 p(load_value<float>(corner, true), load_value<float>(corner + 4, true),
                   load_value<float>(corner + 8, true));
      if (!is_finite(p)) {
        fail(path, "triangle " + std::to_string(t) + " has a non-finite coordinate (" + non_finite_text(p) + ")");
      }
      corners[c] = merger.index_of(p);
    }
    add_polygon(soup, corners, report);
  }
  return soup;
}

// solid name / facet normal x y z / outer loop / vertex x y z (3x) / endloop / endfacet / endsolid
TriangleSoup read_ascii(const std::string& path, std::string_view data, ReadReport& report) {
  report.format = "stl-ascii";
  TextScanner in(data);
  const auto fail_here = [&](const std::string& problem) { fail(path, at_line(in.line()) + problem); };
  const auto next = [&] {
    if (!in.seek_token()) fail(path, "truncated: the file ends inside a facet");
    return in.token();
  };
  const auto expect = [&](std::string_view keyword) {
    const std::string_view token = next();
    if (!equals_ignoring_case(token, keyword)) {
      fail_here("expected '" + std::string(keyword) + "', found " + quoted(token));
    }
  };
  const auto number = [&] {
    const std::string_view token = next();
    double value = 0.0;
    if (!parse_double(token, value)) fail_here(quoted(token) + " is not a number");
    return value;
  };

  TriangleSoup soup;
  CornerMerger merger(soup, data.size() / 500);  // ~250 bytes per facet, half a vertex per facet
  std::vector<std::uint32_t> corners(3);
  GroupTags solids;
  int solid = 0, solids_met = 0;
  const auto start_solid = [&] {
    expect("solid");
    const std::string_view name = in.rest_of_line();
    ++solids_met;
    solid = solids.tag(soup, name.empty() ? "solid_" + std::to_string(solids_met) : std::string(name));
  };
  start_solid();
  for (;;) {
    if (!in.seek_token()) fail(path, "truncated: no 'endsolid'");
    const std::string_view keyword = in.token();
    if (equals_ignoring_case(keyword, "endsolid")) {
      in.skip_line();
      if (!in.seek_token()) break;
      start_solid();  // several solids in one file
      report.patches_from = "stl solids";
      continue;
    }
    if (!equals_ignoring_case(keyword, "facet")) fail_here("expected 'facet' or 'endsolid', found " + quoted(keyword));
    expect("normal");
    for (int k = 0; k < 3; ++k) number();  // recomputed from the corners when needed
    expect("outer");
    expect("loop");
    for (int c = 0; c < 3; ++c) {
      expect("vertex");
      Vec3 p;
      for (int k = 0; k < 3; ++k) p[k] = number();
      if (!is_finite(p)) {
        fail_here("triangle " + std::to_string(report.faces_in_file) + " has a non-finite coordinate (" +
                  non_finite_text(p) + ")");
      }
      corners[c] = merger.index_of(p);
    }
    expect("endloop");
    expect("endfacet");
    add_polygon(soup, corners, report, solid);
  }
  return soup;
}

}  // namespace

TriangleSoup read_stl(const std::string& path, std::string_view data, ReadReport& report) {
  if (data.size() >= header_bytes + 4) {
    const auto n_triangles = load_value<std::uint32_t>(data.data() + header_bytes, true);
    const std::uint64_t expected = header_bytes + 4 + std::uint64_t{n_triangles} * triangle_bytes;
    if (data.size() == expected) return read_binary(path, data, n_triangles, report);
    if (!looks_like_ascii(data)) {
      const std::string problem = data.size() < expected ? "truncated binary STL: " : "binary STL with trailing data: ";
      fail(path, problem + std::to_string(data.size()) + " bytes, but the header announces " +
                     std::to_string(n_triangles) + " triangles (" + std::to_string(expected) + " bytes)");
    }
  } else if (!looks_like_ascii(data)) {
    fail(path, "truncated binary STL: " + std::to_string(data.size()) + " bytes, shorter than the 84-byte header");
  }
  return read_ascii(path, data, report);
}

}  // namespace meshprep::detail
