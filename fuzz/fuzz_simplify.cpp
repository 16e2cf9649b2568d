// libFuzzer target: simplify (preprocess/) on a tiny mesh decoded from the bytes (scripts/fuzz.sh
// runs it). It may refuse the mesh only with InvalidInput; what it returns must be a mesh: corner
// indices in range, finite points, no more faces than it was given, the counts it reports.
//
// The bytes: a byte for the number of points (4 to 19), one for the options (cost, polish, the
// smallest angle), one for the ratio of faces kept (1/16 to 16/16), then three bytes per point
// (coordinates 0 to 15 on a grid, halved or not by the fourth byte's bits: flat, folded and
// coincident places are common), then three bytes per face (corner indices modulo the number of
// points), up to 48 faces; the faces mesh_from_soup cannot add are left out.
#include "fuzz_support.h"

#include "meshprep/core/mesh.h"
#include "meshprep/preprocess/simplify/simplify.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace meshprep;
  if (size < 3) return 0;
  const std::size_t point_count = 4 + data[0] % 16;
  SimplifyParams params;
  params.cost = static_cast<CollapseCost>(data[1] % 3);
  params.polish = (data[1] >> 2 & 1) != 0;
  params.min_angle_deg = (data[1] >> 3 & 1) ? 0 : 20;
  params.keep_ratio = (1 + data[2] % 16) / 16.0;
  std::size_t at = 3;
  if (size < at + 3 * point_count) return 0;
  TriangleSoup soup;
  soup.points = fuzz::grid_points_from_bytes(data, at, point_count);
  soup.triangles = fuzz::faces_from_bytes(data, size, at + 3 * point_count, point_count, /*max_faces=*/48);
  TriMesh mesh = mesh_from_soup(soup);
  const std::size_t faces_before = mesh.n_faces();
  fuzz::refuse_only_with_meshprep_errors([&] {
    const SimplifyResult result = simplify(mesh, params);
    const TriangleSoup output = soup_from_mesh(mesh);
    fuzz::require(result.faces_before == faces_before, "faces_before counts the faces given");
    fuzz::require(result.faces_after == output.triangles.size(), "faces_after counts the faces returned");
    fuzz::require(output.triangles.size() <= faces_before, "simplify adds no face");
    for (const Vec3& p : output.points) fuzz::require(p.allFinite(), "every point is finite");
    for (const Triangle& t : output.triangles)
      for (const std::uint32_t corner : t) fuzz::require(corner < output.points.size(), "every corner indexes a point");
  });
  return 0;
}
