// libFuzzer target: the self-intersection search of quality/ on a tiny triangle soup decoded from
// the bytes, against the brute-force reference in exact integer arithmetic
// (self_intersection_reference.h); any difference aborts (scripts/fuzz.sh runs it).
//
// The bytes: a byte for the number of points (3 to 10), one for a power-of-two scale (2^-20 to
// 2^20, exact, so every answer is the integers' answer), one for the cap, then three bytes per point
// (coordinates 0 to 7: a small grid, so that coplanar, touching and shared-corner cases are
// common), then three bytes per face (corner indices modulo the number of points), up to 12 faces.
#include "fuzz_support.h"
#include "self_intersection_reference.h"

#include "meshprep/quality/self_intersections.h"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace meshprep;
  if (size < 3) return 0;
  const std::size_t point_count = 3 + data[0] % 8;
  const double scale = std::ldexp(1.0, data[1] % 41 - 20);
  const std::size_t cap = data[2] % 4;  // 0: no cap
  std::size_t at = 3;
  if (size < at + 3 * point_count) return 0;
  std::vector<fuzz::IntVec> grid(point_count);
  TriangleSoup soup;
  for (auto& p : grid) {
    for (auto& c : p) c = data[at++] % 8;
    soup.points.push_back(Vec3(static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2])) * scale);
  }
  soup.triangles = fuzz::faces_from_bytes(data, size, at, point_count, /*max_faces=*/12);
  std::vector<std::pair<std::size_t, std::size_t>> expected = fuzz::reference_self_intersections(grid, soup.triangles);
  const SelfIntersections found = find_self_intersections(soup, cap);
  const bool capped = cap > 0 && expected.size() > cap;
  if (capped) expected.resize(cap);
  fuzz::require(found.pairs == expected, "the intersecting pairs are the exact reference's");
  fuzz::require(found.count == expected.size() && found.capped == capped, "count and capped describe the pairs");
  const std::size_t n = soup.triangles.size();
  fuzz::require(found.exact_tests <= n * (n - 1) / 2, "no pair is tested twice");
  return 0;
}
