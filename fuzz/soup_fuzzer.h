#pragma once
/// \file soup_fuzzer.h
/// The body of the mesh reader targets: read_soup on the bytes in memory, format by extension.

#include "fuzz_support.h"
#include "readers.h"

namespace meshprep::fuzz {

/// What io.h promises of a soup it returns: faces, finite points, indices in range.
inline void require_valid_soup(const TriangleSoup& soup, const ReadReport& report) {
  require(!soup.triangles.empty(), "a soup that was read has faces");
  require(report.triangles == soup.triangles.size(), "report.triangles counts the soup's triangles");
  require(report.faces_in_file <= report.triangles, "each face in the file gives at least one triangle");
  for (const Vec3& p : soup.points) require(detail::is_finite(p), "every point is finite");
  for (const Triangle& triangle : soup.triangles)
    for (const std::uint32_t corner : triangle) require(corner < soup.points.size(), "every corner indexes a point");
}

/// Reads the bytes as the file `name` (whose extension chooses the reader) would be read.
inline int fuzz_soup_reader(const std::string& name, const std::uint8_t* data, std::size_t size) {
  refuse_only_with_meshprep_errors([&] {
    ReadReport report;
    const TriangleSoup soup = detail::parse_soup(name, as_text(data, size), &report);
    require_valid_soup(soup, report);
  });
  return 0;
}

}  // namespace meshprep::fuzz
