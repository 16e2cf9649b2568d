#include "meshprep/preprocess/reconstruct/partition_of_unity.h"

#include "meshprep/core/errors.h"
#include "meshprep/quality/statistics.h"

#include <nanoflann.hpp>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <sstream>
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
  if (params.leaf_size < 1 || !(params.enlargement > 1) || !(params.variation_growth >= 1) ||
      !std::isfinite(params.variation_threshold) || !(params.variation_percentile <= 100))
    throw InvalidInput(std::string(who) + ": the leaf size must be at least 1, the enlargement above 1, the variation "
                                          "growth at least 1 and the percentile at most 100");
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
  index_ = std::make_unique<Index>();
  // The cells and the samples' k-d tree do not depend on each other: built side by side.
  tbb::parallel_invoke([&] { split_cells(planar, order, 0, order.size(), footprint_, params.leaf_size, cells); },
                       [&] { index_->samples = std::make_unique<PlanarIndex>(planar); });
  const PlanarIndex& samples = *index_->samples;
  // Each sample's distance to its nearest neighbour in the plane. A height field has one height
  // per place: a sample within 1/10 of the height difference from its nearest neighbour (a
  // duplicate, or a wall steeper than 10:1, which the PCA plane, tilted by it, does not separate)
  // is refused, the pair named by input position.
  std::vector<double> spacing(points.size());
  std::vector<std::uint32_t> nearest_sample(points.size());
  tbb::parallel_for(std::size_t(0), points.size(), [&](std::size_t i) {
    std::uint32_t index[2];
    double squared[2];
    samples.tree.knnSearch(samples.points[i].data(), 2, index, squared);
    spacing[i] = std::sqrt(squared[1]);
    nearest_sample[i] = index[0] == i ? index[1] : index[0];
  });
  for (std::size_t i = 0; i < points.size(); ++i)
    if (spacing[i] <= 0.1 * std::abs(heights[i] - heights[nearest_sample[i]]) || spacing[i] == 0) {
      const std::size_t a = std::min<std::size_t>(i, nearest_sample[i]), b = std::max<std::size_t>(i, nearest_sample[i]);
      throw InvalidInput(std::string(who) + ": points " + std::to_string(a + 1) + " and " + std::to_string(b + 1) +
                         " (in input order) lie at the same place of the reference plane, or one above the other "
                         "(a height field has one height per place)");
    }
  const auto middle = spacing.begin() + static_cast<std::ptrdiff_t>(spacing.size() / 2);
  std::nth_element(spacing.begin(), middle, spacing.end());
  median_spacing_ = *middle;
  // Points along a curve span no surface: their spread across the plane's second axis must reach
  // about one spacing between neighbouring samples (two samples across). sqrt(12 lambda) is the
  // width of a uniform spread of variance lambda, the PCA's middle eigenvalue; under half the
  // spacing no strip two samples wide fits. (1,000 points on a line with 1e-9 noise: width 3e-9
  // against a spacing of 3.7e-3 made a grid of 178 k needles.)
  const double width = std::sqrt(12 * frame_.eigenvalues.y());
  if (!(width >= 0.5 * median_spacing_)) {
    std::ostringstream message;
    message << "the points are nearly collinear (along a curve, not over a surface): they spread " << width
            << " across it, under half the spacing between neighbouring samples (" << median_spacing_ << ")";
    throw InvalidInput(message.str());
  }
  const std::size_t grown_count = std::min(
      points.size(), static_cast<std::size_t>(std::ceil(static_cast<double>(params.neighbors) *
                                                        params.variation_growth * params.variation_growth)));
  centres_.resize(cells.size());
  radii_.resize(cells.size());
  variation_.resize(cells.size());
  // Every patch is independent (its own slots): built in parallel, the same result on any thread count.
  // First each cell's centre, support and sigma (PCA of the samples nearest to the centre)...
  std::vector<std::vector<std::uint32_t>> nearest(cells.size());
  tbb::parallel_for(std::size_t(0), cells.size(), [&](std::size_t c) {
    centres_[c] = cells[c].center();
    radii_[c] = std::max(params.enlargement * 0.5 * cells[c].diagonal().norm(), 1e-300);
    nearest[c].resize(params.neighbors);
    std::vector<double> squared(params.neighbors);
    nearest[c].resize(samples.tree.knnSearch(centres_[c].data(), params.neighbors, nearest[c].data(), squared.data()));
    std::vector<Vec3> local;
    for (const std::uint32_t s : nearest[c]) local.emplace_back(samples.points[s].x(), samples.points[s].y(), heights[s]);
    variation_[c] = pca_frame(local).surface_variation();
  });
  threshold_ = params.variation_threshold;
  if (params.variation_percentile >= 0) {
    std::vector<double> sigma = variation_;
    threshold_ = params.variation_percentile > 0 ? percentile(sigma, params.variation_percentile / 100)
                                                 : *std::min_element(sigma.begin(), sigma.end());
  }
  // ... then, where sigma is above the threshold, more samples and a larger support; the patches.
  std::vector<char> grown(cells.size(), 0);
  std::vector<std::optional<DuchonSpline>> fits(cells.size());
  tbb::parallel_for(std::size_t(0), cells.size(), [&](std::size_t c) {
    if (variation_[c] > threshold_ && grown_count > nearest[c].size()) {
      nearest[c].resize(grown_count);
      std::vector<double> squared(grown_count);
      nearest[c].resize(samples.tree.knnSearch(centres_[c].data(), grown_count, nearest[c].data(), squared.data()));
      radii_[c] *= params.variation_growth;
      grown[c] = 1;
    }
    std::vector<Vector2d> sites;
    Eigen::VectorXd values(static_cast<Eigen::Index>(nearest[c].size()));
    for (const std::uint32_t s : nearest[c]) {
      values[static_cast<Eigen::Index>(sites.size())] = heights[s];
      sites.push_back(samples.points[s]);
    }
    // The spline's own message names the class (DuchonSpline: ...); the user needs the place.
    const auto at_the_place = [&](const Error& e) {
      const Vec3 centre = frame_.to_world(Vec3(centres_[c].x(), centres_[c].y(), 0));
      std::ostringstream message;
      message << "the local surface of the " << sites.size() << " points around (" << centre.x() << ", " << centre.y()
              << ", " << centre.z() << ") cannot be fitted: their layout is degenerate (" << e.what() << ")";
      return message.str();
    };
    try {
      fits[c].emplace(sites, values, params.polynomial);
    } catch (const InvalidInput& e) {
      throw InvalidInput(at_the_place(e));
    } catch (const SolverError& e) {
      throw SolverError(at_the_place(e));
    }
  });
  fits_.reserve(cells.size());
  for (std::optional<DuchonSpline>& fit : fits) fits_.push_back(std::move(*fit));
  grown_ = static_cast<std::size_t>(std::count(grown.begin(), grown.end(), 1));
  largest_radius_ = *std::max_element(radii_.begin(), radii_.end());
  index_->centres = std::make_unique<PlanarIndex>(centres_);
}

PartitionOfUnity::~PartitionOfUnity() = default;
PartitionOfUnity::PartitionOfUnity(PartitionOfUnity&&) noexcept = default;
PartitionOfUnity& PartitionOfUnity::operator=(PartitionOfUnity&&) noexcept = default;

std::size_t PartitionOfUnity::patches() const { return radii_.size(); }

const std::vector<Vector2d>& PartitionOfUnity::sample_positions() const { return index_->samples->points; }

double PartitionOfUnity::median_sample_spacing() const { return median_spacing_; }

void PartitionOfUnity::add_patch(std::size_t p, double x, double y, double squared_distance, Value& sum) const {
  const double w = wendland_weight(std::sqrt(squared_distance) / radii_[p]);
  if (w <= 0) return;
  sum.weight_sum += w;
  sum.height += w * fits_[p].evaluate(x, y);
  sum.variation += w * variation_[p];
}

void PartitionOfUnity::Value::normalise() {
  if (weight_sum <= 0) return;
  height /= weight_sum;
  variation /= weight_sum;
}

PartitionOfUnity::Value PartitionOfUnity::evaluate(double x, double y) const {
  const double query[2] = {x, y};
  thread_local std::vector<std::pair<std::uint32_t, double>> within;  // reused: no allocation per call
  within.clear();
  nanoflann::SearchParams search;
  search.sorted = false;
  index_->centres->tree.radiusSearch(query, largest_radius_ * largest_radius_, within, search);
  std::sort(within.begin(), within.end());  // in patch order: deterministic sums, equal to evaluate_grid's
  Value value;
  for (const auto& [p, squared] : within) add_patch(p, x, y, squared, value);
  value.normalise();
  return value;
}

std::vector<PartitionOfUnity::Value> PartitionOfUnity::evaluate_grid(const PlaneGrid& grid) const {
  // Square tiles of vertices, in parallel. Each adds up, in patch order, the patches whose
  // support's bounding box meets it: no search per vertex, no sums across tiles, and sums that do
  // not depend on the thread count.
  constexpr std::size_t kTile = 16;
  const std::size_t tiles_x = (grid.columns + kTile - 1) / kTile, tiles_y = (grid.rows + kTile - 1) / kTile;
  struct Box {
    std::size_t i0, i1, j0, j1;  // vertex columns [i0, i1), rows [j0, j1)
  };
  std::vector<Box> boxes(patches());
  std::vector<std::vector<std::uint32_t>> meeting(tiles_x * tiles_y);  // the patches meeting each tile
  auto first_at_or_after = [](double index, std::size_t count) {
    return static_cast<std::size_t>(std::clamp(std::ceil(index), 0.0, static_cast<double>(count)));
  };
  for (std::size_t p = 0; p < patches(); ++p) {
    const Vector2d low = (centres_[p] - Vector2d::Constant(radii_[p]) - grid.origin).cwiseQuotient(grid.step);
    const Vector2d high = (centres_[p] + Vector2d::Constant(radii_[p]) - grid.origin).cwiseQuotient(grid.step);
    Box& b = boxes[p];
    b = {first_at_or_after(low.x(), grid.columns), first_at_or_after(std::floor(high.x()) + 1, grid.columns),
         first_at_or_after(low.y(), grid.rows), first_at_or_after(std::floor(high.y()) + 1, grid.rows)};
    if (b.i0 >= b.i1 || b.j0 >= b.j1) continue;
    for (std::size_t tj = b.j0 / kTile; tj <= (b.j1 - 1) / kTile; ++tj)
      for (std::size_t ti = b.i0 / kTile; ti <= (b.i1 - 1) / kTile; ++ti)
        meeting[tj * tiles_x + ti].push_back(static_cast<std::uint32_t>(p));
  }
  std::vector<Value> values(grid.columns * grid.rows);
  tbb::parallel_for(std::size_t(0), meeting.size(), [&](std::size_t t) {
    const std::size_t i_begin = t % tiles_x * kTile, i_end = std::min(i_begin + kTile, grid.columns);
    const std::size_t j_begin = t / tiles_x * kTile, j_end = std::min(j_begin + kTile, grid.rows);
    for (const std::uint32_t p : meeting[t]) {
      const Box& b = boxes[p];
      for (std::size_t j = std::max(b.j0, j_begin); j < std::min(b.j1, j_end); ++j)
        for (std::size_t i = std::max(b.i0, i_begin); i < std::min(b.i1, i_end); ++i) {
          const Vector2d q = grid.at(i, j);
          add_patch(p, q.x(), q.y(), (q - centres_[p]).squaredNorm(), values[j * grid.columns + i]);
        }
    }
    for (std::size_t j = j_begin; j < j_end; ++j)
      for (std::size_t i = i_begin; i < i_end; ++i) values[j * grid.columns + i].normalise();
  });
  return values;
}

}  // namespace meshprep
