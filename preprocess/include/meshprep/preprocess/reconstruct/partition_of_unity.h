#pragma once
/// \file partition_of_unity.h
/// The paper's Section 3 interpolant of scattered points over a disc-like domain: a partition of
/// unity (modified Shepard method) over the cells of a k-d tree with leaf size K. Each cell is a
/// subdomain centred at its centre c_i with radius R_i = enlargement x half its diagonal (the cells
/// tile the domain, so every point of the data's bounding rectangle lies in at least one
/// support); its local approximant f_i is a height map interpolating the `neighbors` samples
/// nearest to c_i: Duchon's spline with phi = r^(5/2) (thin_plate_spline.h), eq. (3)'s thin plate
/// with a slightly smoother kernel; the blend is
///   f(x) = sum_i W_i(x) f_i(x) / sum_i W_i(x),   W_i(x) = W(|x - c_i| / R_i),
/// with Wendland's compactly supported W(r) = (1 - r)^4 (4 r + 1) for r < 1, 0 beyond.
/// Heights are measured from the PCA plane of the whole set (not z-up): local_frame.h.
/// Curvature analysis (the paper's Section 3): each patch's surface variation sigma (PCA of its
/// samples, local_frame.h); where sigma exceeds a threshold the patch "attracts data from
/// neighbouring cells and increases its r-sphere": its support radius and its sample count grow.
/// docs/reconstruction.md has the measurements behind the defaults (jacksboro DEM: RMS 18.53 m
/// on held-out points; the global thin-plate spline: 18.7 m).

#include "meshprep/core/mesh.h"
#include "meshprep/preprocess/rbf/local_frame.h"
#include "meshprep/preprocess/rbf/thin_plate_spline.h"

#include <Eigen/Core>

#include <cstddef>
#include <memory>
#include <vector>

namespace meshprep {

struct PartitionOfUnityParams {
  std::size_t leaf_size = 16;  ///< K: at most this many samples per k-d tree cell
  std::size_t neighbors = 40;  ///< samples interpolated by each cell's patch
  /// Support radius / half the cell's diagonal, > 1 (any value covers the cell). 1.3: 3.1 patches
  /// per point; 1.5 (4.1) costs 30 % more evaluation for 0.007 m of RMS on the Jacksboro DEM.
  double enlargement = 1.3;
  HeightMapPolynomial polynomial = HeightMapPolynomial::linear;
  /// Patches whose sigma exceeds the threshold get `variation_growth` x the support radius and
  /// variation_growth^2 x the samples (the same sample density over the larger disc). The
  /// threshold is this percentile (0..100) of the patches' sigma, an adaptive rule; a negative
  /// percentile means the fixed `variation_threshold` instead (the paper's 0.3). On terrain sigma
  /// stays below ~0.02, so 0.3 never fires; the 90th percentile measured best on the Jacksboro DEM
  /// (docs/reconstruction.md).
  double variation_percentile = 90;
  double variation_threshold = 0.3;
  double variation_growth = 1.5;  ///< >= 1
};

/// A regular grid of the reference plane: vertex (i, j) at origin + (i step.x, j step.y), stored
/// row by row (index j * columns + i).
struct PlaneGrid {
  Eigen::Vector2d origin = Eigen::Vector2d::Zero(), step = Eigen::Vector2d::Ones();
  std::size_t columns = 0, rows = 0;
  Eigen::Vector2d at(std::size_t i, std::size_t j) const {
    return origin + Eigen::Vector2d(static_cast<double>(i) * step.x(), static_cast<double>(j) * step.y());
  }
};

/// Wendland's C2 function (1 - r)^4 (4 r + 1) on [0, 1), 0 for r >= 1.
double wendland_weight(double r);

class PartitionOfUnity {
 public:
  /// \throws InvalidInput if a coordinate is not finite, there are fewer points than
  ///         params.neighbors, the parameters are out of range, two samples lie at the same (x, y)
  ///         of the plane (named by their input positions), or a patch cannot be built (all its
  ///         samples collinear).
  explicit PartitionOfUnity(const std::vector<Vec3>& points, const PartitionOfUnityParams& params = {});
  ~PartitionOfUnity();
  PartitionOfUnity(PartitionOfUnity&&) noexcept;
  PartitionOfUnity& operator=(PartitionOfUnity&&) noexcept;

  /// The PCA frame of all points: local (x, y) span the reference plane, z is the height.
  const LocalFrame& frame() const { return frame_; }
  /// The samples' bounding rectangle in the frame's (x, y).
  const Eigen::AlignedBox2d& footprint() const { return footprint_; }
  std::size_t patches() const;
  /// The samples' (x, y) in the frame, in input order.
  const std::vector<Eigen::Vector2d>& sample_positions() const;
  /// The median, over the samples, of the distance (in the plane) to their nearest neighbour.
  double median_sample_spacing() const;

  struct Value {
    double height = 0;      ///< f(x, y), the height above the reference plane
    double weight_sum = 0;  ///< sum_i W_i(x, y); 0 outside every support (height then 0)
    double variation = 0;   ///< the patches' sigma blended alike, sum_i W_i sigma_i / sum_i W_i
    void normalise();       ///< from the weighted sums to the blend (divides by weight_sum if > 0)
  };
  /// f at frame coordinates (x, y).
  Value evaluate(double x, double y) const;
  /// f at every grid vertex, computed tile by tile in parallel (the sums are taken in patch
  /// order, so the result does not depend on the thread count). Equal to evaluate() at each vertex
  /// up to round-off.
  std::vector<Value> evaluate_grid(const PlaneGrid& grid) const;
  /// Each patch's surface variation sigma (of its samples, before any growth).
  const std::vector<double>& patch_variation() const { return variation_; }
  /// The sigma threshold applied (params.variation_threshold or the percentile's value).
  double variation_threshold() const { return threshold_; }
  /// Patches whose support grew because their sigma exceeded the threshold.
  std::size_t grown_patches() const { return grown_; }
  /// The surface point above frame coordinates (x, y), in world coordinates.
  Vec3 surface_point(double x, double y) const { return frame_.to_world(Vec3(x, y, evaluate(x, y).height)); }

 private:
  // Adds patch p's weighted height and sigma at (x, y), at this squared distance from its centre.
  void add_patch(std::size_t p, double x, double y, double squared_distance, Value& sum) const;

  struct Index;
  LocalFrame frame_;
  Eigen::AlignedBox2d footprint_;
  std::vector<Eigen::Vector2d> centres_;
  std::vector<double> radii_, variation_;
  std::vector<DuchonSpline> fits_;
  std::size_t grown_ = 0;
  double median_spacing_ = 0;
  double threshold_ = 0;
  double largest_radius_ = 0;
  std::unique_ptr<Index> index_;  // k-d trees over the samples and the cell centres
};

}  // namespace meshprep
