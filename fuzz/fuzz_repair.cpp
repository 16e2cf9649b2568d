// libFuzzer target: repair (preprocess/) on a tiny soup decoded from the bytes (scripts/fuzz.sh runs
// it). It may refuse the soup only with meshprep's errors; what it returns must be a soup: corner
// indices in range, finite points; and when it says its last search found no intersecting pair
// (free_of_self_intersections, which check_fem_readiness then trusts), a search finds none.
//
// The bytes: a byte for the number of points (4 to 19), one for the options (keep_cavities, and
// max_hole auto, 0 or 3), then three bytes per point (coordinates 0 to 15 on a grid, halved or not
// by the fourth byte's bits: coplanar, collinear and coincident places are common, the cut's
// exact arithmetic meets every degenerate case), then three bytes per face (corner indices modulo
// the number of points), up to 32 faces.
#include "fuzz_support.h"

#include "meshprep/core/mesh.h"
#include "meshprep/preprocess/repair/repair.h"
#include "meshprep/quality/self_intersections.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace meshprep;
  if (size < 2) return 0;
  const std::size_t point_count = 4 + data[0] % 16;
  RepairParams params;
  params.keep_cavities = (data[1] & 1) != 0;
  if (data[1] >> 1 & 1) params.max_hole = (data[1] >> 2 & 1) ? 3.0 : 0.0;
  // Both routes, the envelope's on the coarsest grid (its cost grows with the cube of the cells:
  // at 16, one input of a sanitizer build took 11 s).
  params.route = (data[1] >> 3) % 3 == 0 ? RepairRoute::automatic : (data[1] >> 3) % 3 == 1 ? RepairRoute::exact
                                                                                           : RepairRoute::envelope;
  params.envelope_cells = 8;
  std::size_t at = 2;
  if (size < at + 3 * point_count) return 0;
  TriangleSoup soup;
  soup.points = fuzz::grid_points_from_bytes(data, at, point_count);
  soup.triangles = fuzz::faces_from_bytes(data, size, at + 3 * point_count, point_count, /*max_faces=*/32);
  fuzz::refuse_only_with_meshprep_errors([&] {
    const RepairResult result = repair(soup, params);
    for (const Vec3& p : soup.points) fuzz::require(p.allFinite(), "every point is finite");
    for (const Triangle& t : soup.triangles)
      for (const std::uint32_t corner : t) fuzz::require(corner < soup.points.size(), "every corner indexes a point");
    if (result.envelope)
      fuzz::require(find_self_intersections(soup).count == 0, "the envelope's faces cross nowhere");
    if (result.free_of_self_intersections)
      fuzz::require(find_self_intersections(soup).count == 0, "no intersecting pair where the repair found none");
  });
  return 0;
}
