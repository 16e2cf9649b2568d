#include "meshprep/core/size_field.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/parameter.h"
#include "meshprep/core/patch_names.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <set>

namespace meshprep {

Length parse_length(const std::string& text, const std::string& what) {
  Length length;
  std::string number = text;
  if (!number.empty() && number.back() == '%') {
    number.pop_back();
    length.relative = true;
  }
  char* end = nullptr;
  const double value = number.empty() ? NAN : std::strtod(number.c_str(), &end);
  if (!(end && *end == '\0' && std::isfinite(value) && value > 0))
    throw InvalidInput(what + ": expected a positive length or a percentage of the diagonal such as 2%, not '" + text + "'");
  length.value = length.relative ? value / 100 : value;
  return length;
}

std::string length_text(const Length& length) {
  return length.relative ? parameter_text(100 * length.value) + "%" : parameter_text(length.value);
}

double SizeRegion::distance(const Vec3& x) const {
  if (shape == Shape::sphere) return std::max(0.0, (x - center).norm() - radius);
  return (x - x.cwiseMax(lo).cwiseMin(hi)).norm();
}

// The demands, grouped by length into levels (each twice the last's smallest length) with a k-d
// tree each (nanoflann's dataset interface). A query searches each level only as far as one of its
// demands could still beat the best length found (reach = (best - level's smallest) / slope): with
// one tree, the few shortest demands made every query search a wide ball of long ones (example005:
// 2.8 of its 7.6 s went to the field).
struct SizeField::Levels {
  struct Level {
    std::vector<Vec3> points;
    std::vector<double> lengths;
    double smallest = INFINITY;
    std::size_t kdtree_get_point_count() const { return points.size(); }
    double kdtree_get_pt(std::size_t i, std::size_t dim) const { return points[i][static_cast<Eigen::Index>(dim)]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
      return false;
    }
    using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Level>, Level, 3>;
    std::unique_ptr<Tree> tree;
  };
  std::vector<Level> levels;  // finest first
  std::size_t count = 0;

  // min(best, min over demands s of h_s + slope |x - s|).
  double lowest(const Vec3& x, double best, double slope) const {
    const double query[3] = {x.x(), x.y(), x.z()};
    thread_local std::vector<std::pair<unsigned, double>> within;
    nanoflann::SearchParams search;
    search.sorted = false;
    for (const Level& level : levels) {
      if (level.smallest >= best) break;  // the levels after are longer still
      if (level.points.empty()) continue;
      if (!(slope > 0)) {  // grading 1: every demand holds everywhere
        best = std::min(best, level.smallest);
        continue;
      }
      unsigned nearest = 0;
      double squared = 0;
      level.tree->knnSearch(query, 1, &nearest, &squared);
      best = std::min(best, level.lengths[nearest] + slope * std::sqrt(squared));
      const double reach = (best - level.smallest) / slope;
      if (reach <= 0) continue;
      within.clear();
      level.tree->radiusSearch(query, reach * reach, within, search);
      for (const auto& [i, d2] : within) best = std::min(best, level.lengths[i] + slope * std::sqrt(d2));
    }
    return best;
  }
};

SizeField::SizeField(const std::vector<SizeDemand>& demands, double longest, double grading, double shortest,
                     std::vector<RegionDemand> regions)
    : levels_(std::make_unique<Levels>()), regions_(std::move(regions)), longest_(longest), floor_(shortest),
      slope_(grading - 1) {
  if (!(longest > 0 && std::isfinite(longest)))
    throw InvalidInput("size field: the longest length must be positive and finite, not " + parameter_text(longest));
  if (!(shortest >= 0 && shortest <= longest))
    throw InvalidInput("size field: the shortest length must be in [0, " + parameter_text(longest) + "], not " +
                       parameter_text(shortest));
  if (!(grading >= 1 && std::isfinite(grading)))
    throw InvalidInput("size field: the grading must be at least 1, not " + parameter_text(grading));
  shortest_demand_ = longest_;
  for (const RegionDemand& r : regions_) {
    if (!(r.length > 0)) throw InvalidInput("size field: a region's length must be positive, not " + parameter_text(r.length));
    shortest_demand_ = std::min(shortest_demand_, std::max(r.length, floor_));
  }
  for (const SizeDemand& d : demands)
    if (d.length < longest_) shortest_demand_ = std::min(shortest_demand_, std::max(d.length, floor_));
  for (const SizeDemand& d : demands) {
    if (!(d.length < longest_)) continue;
    const double length = std::max(d.length, floor_);
    const auto level = static_cast<std::size_t>(std::floor(std::log2(length / shortest_demand_)));
    if (levels_->levels.size() <= level) levels_->levels.resize(level + 1);
    Levels::Level& l = levels_->levels[level];
    l.points.push_back(d.point);
    l.lengths.push_back(length);
    l.smallest = std::min(l.smallest, length);
    ++levels_->count;
  }
  for (Levels::Level& level : levels_->levels) {
    if (level.points.empty()) continue;
    level.tree = std::make_unique<Levels::Level::Tree>(3, level, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    level.tree->buildIndex();
  }
}

SizeField::~SizeField() = default;
SizeField::SizeField(SizeField&&) noexcept = default;
SizeField& SizeField::operator=(SizeField&&) noexcept = default;

std::size_t SizeField::demands() const { return levels_->count; }

double SizeField::operator()(const Vec3& x) const {
  const Vec3 at = x - offset_;
  double best = longest_;
  for (const RegionDemand& r : regions_) best = std::min(best, r.length + slope_ * r.region.distance(at));
  return scale_ * std::max(floor_, levels_->lowest(at, best, slope_));
}

double SizeParams::grading_used() const { return grading.value_or(any_set() ? kSizeGrading : kSurfaceGrading); }

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
    const Vec3 &a = surface.points[t[0]], &b = surface.points[t[1]], &c = surface.points[t[2]];
    const double length = ((b - a).norm() + (c - b).norm() + (a - c).norm()) / 3;
    if (length > 0) demands.push_back({(a + b + c) / 3.0, length});
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
