#include "meshprep/preprocess/partition_of_unity.h"

#include "meshprep/core/errors.h"

#include <nanoflann.hpp>


#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace meshprep {
namespace {

using Eigen::Vector2d;

// nanoflann's dataset interface over 2D points.
struct PlanarPoints {
  const std::vector<Vector2d>* points;
  std::size_t kdtree_get_point_count() const { return points->size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const { return (*points)[i][static_cast<Eigen::Index>(dim)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using PlanarTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PlanarPoints>, PlanarPoints, 2>;

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

// A k-d tree that owns the points it indexes. It lives on the heap and never moves (the tree
// points into it), so a moved PartitionOfUnity keeps valid trees.
struct PlanarIndex {
  std::vector<Vector2d> points;
  PlanarPoints adaptor{&points};
  PlanarTree tree{2, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(10)};
  explicit PlanarIndex(std::vector<Vector2d> p) : points(std::move(p)) { tree.buildIndex(); }
};

struct PartitionOfUnity::Index {
  std::unique_ptr<PlanarIndex> samples, centres;
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

  index_ = std::make_unique<Index>();
  index_->samples = std::make_unique<PlanarIndex>(std::move(planar));
  const PlanarIndex& samples = *index_->samples;
  const std::vector<Vector2d>& sample_points = samples.points;
  std::vector<Vector2d> centres;
  const std::size_t k = params.neighbors;
  std::vector<std::uint32_t> nearest(k);
  std::vector<double> squared(k);
  std::vector<Vector2d> sites(k);
  Eigen::VectorXd values(static_cast<Eigen::Index>(k));
  for (const Eigen::AlignedBox2d& cell : cells) {
    const Vector2d centre = cell.center();
    const double query[2] = {centre.x(), centre.y()};
    samples.tree.knnSearch(query, k, nearest.data(), squared.data());
    for (std::size_t j = 0; j < k; ++j) {
      sites[j] = sample_points[nearest[j]];
      values[static_cast<Eigen::Index>(j)] = heights[nearest[j]];
    }
    centres.push_back(centre);
    radii_.push_back(std::max(params.enlargement * 0.5 * cell.diagonal().norm(), 1e-300));
    largest_radius_ = std::max(largest_radius_, radii_.back());
    fits_.emplace_back(sites, values, params.polynomial);
  }
  index_->centres = std::make_unique<PlanarIndex>(std::move(centres));
}

PartitionOfUnity::~PartitionOfUnity() = default;
PartitionOfUnity::PartitionOfUnity(PartitionOfUnity&&) noexcept = default;
PartitionOfUnity& PartitionOfUnity::operator=(PartitionOfUnity&&) noexcept = default;

std::size_t PartitionOfUnity::patches() const { return radii_.size(); }

double PartitionOfUnity::nearest_sample_distance(double x, double y) const {
  std::uint32_t index = 0;
  double squared = 0;
  const double query[2] = {x, y};
  index_->samples->tree.knnSearch(query, 1, &index, &squared);
  return std::sqrt(squared);
}

double PartitionOfUnity::median_sample_spacing() const {
  std::vector<double> spacing;
  spacing.reserve(index_->samples->points.size());
  std::uint32_t index[2];
  double squared[2];
  for (const Vector2d& p : index_->samples->points) {
    const double query[2] = {p.x(), p.y()};
    index_->samples->tree.knnSearch(query, 2, index, squared);
    spacing.push_back(std::sqrt(squared[1]));
  }
  const auto middle = spacing.begin() + static_cast<std::ptrdiff_t>(spacing.size() / 2);
  std::nth_element(spacing.begin(), middle, spacing.end());
  return *middle;
}

PartitionOfUnity::Value PartitionOfUnity::evaluate(double x, double y) const {
  const double query[2] = {x, y};
  thread_local std::vector<std::pair<std::uint32_t, double>> within;  // reused: no allocation per call
  within.clear();
  nanoflann::SearchParams search;
  search.sorted = false;
  index_->centres->tree.radiusSearch(query, largest_radius_ * largest_radius_, within, search);
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
