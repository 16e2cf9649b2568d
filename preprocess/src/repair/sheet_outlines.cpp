#include "repair/sheet_outlines.h"

#include "shared/triangle_angles.h"

#include "meshprep/core/union_find.h"

#include <cmath>

namespace meshprep::detail {

// With a_f a face's area times its unit normal, R = sum a_f = (P - N) d and sum |a_f . d| = P + N.
// R is zero for a closed surface (the divergence theorem: every shadow is cast twice, once by a
// face turned each way), and for a surface with holes it is the sum of its loops' vector areas
// (Stokes), so a closed surface missing a part has R = the missing part's vector area, small
// against P + N. A spherical cap of half angle t gives 1 up to t = 90 degrees (every bowl no
// deeper than a hemisphere, as an open box, is a height field), then sin^2 t / (1 + cos^2 t): 0.8
// at 109.5 degrees, 1/2 at 125, 0 for the whole sphere. Neither scale nor steepness changes it: a
// graph z = h(x, y) with mean gradient g has R along (-g, 1), so a face turns away only where the
// slope against g exceeds 1 / |g| (80 degrees under a mean tilt of 10).
std::vector<LoopSheet> sheet_outlines(const TriangleSoup& soup, const std::vector<LoopBorder>& loops) {
  UnionFind components(soup.points.size());
  for (const Triangle& t : soup.triangles) {
    components.unite(t[0], t[1]);
    components.unite(t[0], t[2]);
  }
  const auto component = [&](std::uint32_t face) { return components.find(soup.triangles[face][0]); };
  // By component (its lowest vertex): d, P - N and P + N.
  std::vector<Vec3> direction(soup.points.size(), Vec3::Zero());
  std::vector<double> signed_shadow(soup.points.size(), 0), shadow(soup.points.size(), 0);
  std::vector<Vec3> area_normals(soup.triangles.size());
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    area_normals[f] = area_normal(soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]) / 2;
    direction[component(static_cast<std::uint32_t>(f))] += area_normals[f];
  }
  for (std::size_t c = 0; c < direction.size(); ++c)
    if (direction[c].norm() > 0) {
      signed_shadow[c] = direction[c].norm();
      direction[c].normalize();
    }
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const std::uint32_t c = component(static_cast<std::uint32_t>(f));
    shadow[c] += std::abs(area_normals[f].dot(direction[c]));
  }
  // A sheet's outline runs as its faces do, around the shadow along d; a hole in it runs the other
  // way (Stokes again: the loops' vector areas sum to R).
  std::vector<LoopSheet> sheets(loops.size());
  std::vector<std::size_t> outline(soup.points.size(), loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const std::uint32_t c = component(loops[l].face);
    sheets[l].one_sidedness = shadow[c] > 0 ? signed_shadow[c] / shadow[c] : 0;
    if (!loops[l].closes) continue;
    if (outline[c] == loops.size() ||
        loops[l].vector_area.dot(direction[c]) > loops[outline[c]].vector_area.dot(direction[c]))
      outline[c] = l;
  }
  for (const std::size_t l : outline)
    if (l < loops.size()) sheets[l].outline = true;
  return sheets;
}

}  // namespace meshprep::detail
