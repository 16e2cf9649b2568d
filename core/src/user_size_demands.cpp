#include "meshprep/core/user_size_demands.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/patch_names.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <string>

namespace meshprep {

namespace {

std::string lower_case(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

using Corners = std::array<Vec3, 3>;

// Demands of `length` over the triangle, cut into quarters until no piece is longer than `spacing`:
// one at each piece's centroid.
void cover_triangle(const Corners& c, double spacing, double length, std::vector<SizeDemand>& demands) {
  const double longest = std::max({(c[1] - c[0]).norm(), (c[2] - c[1]).norm(), (c[0] - c[2]).norm()});
  if (longest <= spacing) {
    demands.push_back({(c[0] + c[1] + c[2]) / 3.0, length});
    return;
  }
  const Vec3 ab = 0.5 * (c[0] + c[1]), bc = 0.5 * (c[1] + c[2]), ca = 0.5 * (c[2] + c[0]);
  for (const Corners& piece : {Corners{c[0], ab, ca}, Corners{ab, c[1], bc}, Corners{ca, bc, c[2]}, Corners{ab, bc, ca}})
    cover_triangle(piece, spacing, length, demands);
}

// Where the user set no size, the surface's own density: at each face's centroid, the mean of
// its edges (Gmsh's default, the size at the boundary's points extended into the volume).
void add_density_demands(const TriangleSoup& surface, std::vector<SizeDemand>& demands) {
  for (const auto& t : surface.triangles) {
    const SizeDemand own = face_density_demand(surface.points[t[0]], surface.points[t[1]], surface.points[t[2]]);
    if (own.length > 0) demands.push_back(own);
  }
}

double diagonal_of(const TriangleSoup& surface) {
  if (surface.points.empty()) return 0;
  Vec3 lo = surface.points.front(), hi = lo;
  for (const Vec3& p : surface.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

}  // namespace

std::vector<SizeDemand> patch_size_demands(const SizeParams& params, const TriangleSoup& surface, double diagonal) {
  std::vector<SizeDemand> demands;
  if (params.patch_sizes.empty()) return demands;
  // Each tag's name as the writers give it, matched without regard to case (names are distinct so).
  std::map<std::string, int> tags;
  std::string known;
  for (const int tag : std::set<int>(surface.patches.begin(), surface.patches.end())) {
    const std::string name = tag_name(surface.patch_names, tag, "patch");
    tags.emplace(lower_case(name), tag);
    known += (known.empty() ? "" : ", ") + name;
  }
  std::map<int, double> length_of_tag;
  for (const auto& [name, size] : params.patch_sizes) {
    const auto tag = tags.find(lower_case(name));
    if (tag == tags.end())
      throw InvalidInput("size: no patch named '" + name + "' (" +
                         (known.empty() ? std::string("the surface has no patches") : "the surface's patches: " + known) +
                         ")");
    length_of_tag[tag->second] = size.resolved(diagonal);
  }
  for (std::size_t t = 0; t < surface.patches.size(); ++t) {
    const auto length = length_of_tag.find(surface.patches[t]);
    if (length == length_of_tag.end()) continue;
    const auto& tri = surface.triangles[t];
    cover_triangle({surface.points[tri[0]], surface.points[tri[1]], surface.points[tri[2]]}, 0.5 * length->second,
                   length->second, demands);
  }
  return demands;
}

std::vector<RegionDemand> region_demands(const SizeParams& params, double diagonal) {
  std::vector<RegionDemand> regions;
  for (const SizeRegion& region : params.regions) regions.push_back({region, region.size.resolved(diagonal)});
  return regions;
}

double smallest_local_size(const SizeParams& params, double diagonal) {
  double smallest = INFINITY;
  for (const auto& [name, size] : params.patch_sizes) smallest = std::min(smallest, size.resolved(diagonal));
  for (const SizeRegion& region : params.regions) smallest = std::min(smallest, region.size.resolved(diagonal));
  return smallest;
}

std::shared_ptr<const SizeField> user_size_field(const SizeParams& params, const TriangleSoup& surface) {
  // Curvature and thickness are the surface's demands (the enhancement's): alone they ask nothing here.
  if (!params.size && !params.size_max && params.patch_sizes.empty() && params.regions.empty()) return nullptr;
  const double diagonal = diagonal_of(surface);
  double longest = params.size ? params.size->resolved(diagonal) : diagonal;
  if (params.size_max) longest = std::min(longest, params.size_max->resolved(diagonal));
  if (!(longest > 0 && std::isfinite(longest))) return nullptr;
  const double shortest = params.size_min ? std::min(params.size_min->resolved(diagonal), longest) : 0;
  std::vector<SizeDemand> demands = patch_size_demands(params, surface, diagonal);
  if (!params.size) add_density_demands(surface, demands);
  return std::make_shared<SizeField>(demands, longest, params.grading_used(), shortest, region_demands(params, diagonal));
}

}  // namespace meshprep
