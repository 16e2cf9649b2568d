#include "meshprep/preprocess/partition_of_unity.h"

#include "planar_tree.h"

#include "meshprep/core/errors.h"


#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace meshprep {
namespace {

using Eigen::Vector2d;

using detail::PlanarPoints;
using detail::PlanarTree;

// The k-d tree's cells: median splits across the longer side until at most `leaf` samples remain.
// Cells tile `cell` (the split planes, not the samples' boxes, bound them).
void split_cells(const std::vector<Vector2d>& points, std::vector<std::uint32_t>& order, std::size_t begin,
                 std::size_t end, const Eigen::AlignedBox2d& cell, std::size_t leaf,
                 std::vector<Eigen::AlignedBox2d>& cells) {
  if (end - begin <= leaf) {
    cells.push_back(cell);
    return;
  }
  const int axis = cell.sizes().x() >= cell.sizes().y() ? 0 : 1;
  const std::size_t middle = (begin + end) / 2;
  std::nth_element(order.begin() + static_cast<std::ptrdiff_t>(begin), order.begin() + static_cast<std::ptrdiff_t>(middle),
                   order.begin() + static_cast<std::ptrdiff_t>(end),
                   [&](std::uint32_t a, std::uint32_t b) { return points[a][axis] < points[b][axis]; });
  const double cut = points[order[middle]][axis];
  Eigen::AlignedBox2d low = cell, high = cell;
  low.max()[axis] = cut;
  high.min()[axis] = cut;
  split_cells(points, order, begin, middle, low, leaf, cells);
  split_cells(points, order, middle, end, high, leaf, cells);
}

}  // namespace

struct PartitionOfUnity::Index {
  PlanarPoints points;
  PlanarTree tree;
  explicit Index(const std::vector<Vector2d>* centres)
      : points{centres}, tree(2, points, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {
    tree.buildIndex();
  }
};

double wendland_weight(double r) {
  if (!(r < 1)) return 0;
  const double s = 1 - r;
  return s * s * s * s * (4 * r + 1);
}

PartitionOfUnity::PartitionOfUnity(const std::vector<Vec3>& points, const PartitionOfUnityParams& params) {
  constexpr const char* who = "partition of unity";
  if (params.leaf_size < 1 || !(params.enlargement > 1))
    throw InvalidInput(std::string(who) + ": the leaf size must be at least 1 and the enlargement above 1");
  if (points.size() < params.neighbors || params.neighbors < 3)
    throw InvalidInput(std::string(who) + ": " + std::to_string(points.size()) + " points, at least " +
                       std::to_string(std::max<std::size_t>(params.neighbors, 3)) + " needed");
  for (const Vec3& p : points)
    if (!p.allFinite()) throw InvalidInput(std::string(who) + ": a coordinate is not finite");
  // The normal's sign is arbitrary in PCA: turn it towards the axis it is closest to (up for a
  // terrain, whatever the axis), so the mesh's faces face that way.
  const Vec3 unoriented = pca_frame(points).normal();
  Eigen::Index axis = 0;
  unoriented.cwiseAbs().maxCoeff(&axis);
  frame_ = pca_frame(points, Vec3::Unit(axis));
  std::vector<Vector2d> planar(points.size());
  std::vector<double> heights(points.size());
  footprint_.setEmpty();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 local = frame_.to_local(points[i]);
    planar[i] = local.head<2>();
    heights[i] = local.z();
    footprint_.extend(planar[i]);
  }

  std::vector<std::uint32_t> order(points.size());
  std::iota(order.begin(), order.end(), 0u);
  std::vector<Eigen::AlignedBox2d> cells;
  split_cells(planar, order, 0, order.size(), footprint_, params.leaf_size, cells);

  PlanarPoints samples{&planar};
  PlanarTree sample_tree(2, samples, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  sample_tree.buildIndex();
  const std::size_t k = params.neighbors;
  std::vector<std::uint32_t> nearest(k);
  std::vector<double> squared(k);
  std::vector<Vector2d> sites(k);
  Eigen::VectorXd values(static_cast<Eigen::Index>(k));
  for (const Eigen::AlignedBox2d& cell : cells) {
    const Vector2d centre = cell.center();
    const double query[2] = {centre.x(), centre.y()};
    sample_tree.knnSearch(query, k, nearest.data(), squared.data());
    for (std::size_t j = 0; j < k; ++j) {
      sites[j] = planar[nearest[j]];
      values[static_cast<Eigen::Index>(j)] = heights[nearest[j]];
    }
    centres_.push_back(centre);
    radii_.push_back(std::max(params.enlargement * 0.5 * cell.diagonal().norm(), 1e-300));
    largest_radius_ = std::max(largest_radius_, radii_.back());
    fits_.emplace_back(sites, values, params.polynomial);
  }
  index_ = std::make_unique<Index>(&centres_);
}

PartitionOfUnity::~PartitionOfUnity() = default;
PartitionOfUnity::PartitionOfUnity(PartitionOfUnity&&) noexcept = default;
PartitionOfUnity& PartitionOfUnity::operator=(PartitionOfUnity&&) noexcept = default;

PartitionOfUnity::Value PartitionOfUnity::evaluate(double x, double y) const {
  const double query[2] = {x, y};
  std::vector<std::pair<std::uint32_t, double>> within;
  nanoflann::SearchParams search;
  search.sorted = false;
  index_->tree.radiusSearch(query, largest_radius_ * largest_radius_, within, search);
  std::sort(within.begin(), within.end());  // a fixed summation order: deterministic results
  Value value;
  double weighted = 0;
  for (const auto& [i, squared] : within) {
    const double w = wendland_weight(std::sqrt(squared) / radii_[i]);
    if (w <= 0) continue;
    value.weight_sum += w;
    weighted += w * fits_[i].evaluate(x, y);
  }
  if (value.weight_sum > 0) value.height = weighted / value.weight_sum;
  return value;
}

}  // namespace meshprep
