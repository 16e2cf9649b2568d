#include "meshprep/core/size_field.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/parameter.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>

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

}  // namespace meshprep
