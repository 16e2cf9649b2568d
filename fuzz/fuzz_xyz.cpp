// libFuzzer target: the XYZ point reader (read_points) on arbitrary bytes (scripts/fuzz.sh runs it).
#include "fuzz_support.h"
#include "readers.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace meshprep;
  fuzz::refuse_only_with_meshprep_errors([&] {
    const PointSet set = detail::parse_points("input.xyz", fuzz::as_text(data, size));
    fuzz::require(!set.points.empty(), "a point set that was read has points");
    fuzz::require(set.normals.empty() || set.normals.size() == set.points.size(), "no normals, or one per point");
    for (const Vec3& p : set.points) fuzz::require(detail::is_finite(p), "every point is finite");
    for (const Vec3& n : set.normals) fuzz::require(detail::is_finite(n), "every normal is finite");
  });
  return 0;
}
