// Reconstruction accuracy and speed on the Jacksboro DEM (issue #5; ../shared/anchors.md):
// predict the grid points of jacksboro_grid.xyz that are not in the 10,000-point sample, and
// time the 300 x 300 (90,000-vertex) mesh, for meshprep's partition of unity and two baselines
// in the same run, and the error of meshprep's meshes themselves (uniform and --adaptive):
//  - plain Shepard: Wendland weights centred on every sample (support = distance to its 20th
//    neighbour), raw heights as the local approximants;
//  - linear interpolation on the Delaunay triangulation of the sample (TetGen's 3D Delaunay of
//    the points lifted onto a paraboloid: its lower hull is the planar Delaunay triangulation).
// Run: build/bin/bench_reconstruct [--leaf-size K] [--neighbors N] [--enlargement E]
//      [--variation-threshold T | --variation-percentile P] [--variation-growth G] [--quadratic]
//      [--no-adaptive]  (needs ../shared/data)
#include "meshprep/core/io.h"
#include "meshprep/preprocess/compose/adaptive_reconstruction.h"
#include "meshprep/preprocess/reconstruct/partition_of_unity.h"
#include "meshprep/preprocess/reconstruct/reconstruct.h"

#include <nanoflann.hpp>
#include <tetgen.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <set>
#include <utility>
#include <string>
#include <vector>

namespace {

using meshprep::Vec3;
using Eigen::Vector2d;

const std::string kPoints = std::string(MESHPREP_SHARED_DATA_DIR) + "/points/";

// The seconds `work` takes, the median of `runs` runs.
double median_seconds(int runs, const std::function<void()>& work) {
  std::vector<double> seconds;
  for (int r = 0; r < runs; ++r) {
    const auto start = std::chrono::steady_clock::now();
    work();
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(seconds.begin(), seconds.begin() + runs / 2, seconds.end());
  return seconds[static_cast<std::size_t>(runs / 2)];
}

// Keeps a result alive so the timed work is not optimised away.
volatile double g_sink = 0;
void benchmark_sink(double value) { g_sink = g_sink + value; }

struct Errors {
  double rms = 0, max = 0;
  std::size_t missing = 0;  // points the method gives no value at (outside its domain)
};

Errors errors(const std::vector<Vec3>& truth, const std::vector<double>& predicted) {
  Errors e;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const double d = predicted[i] - truth[i].z();
    if (std::isnan(d)) {
      ++e.missing;
      continue;
    }
    e.rms += d * d;
    e.max = std::max(e.max, std::abs(d));
  }
  e.rms = std::sqrt(e.rms / static_cast<double>(truth.size() - e.missing));
  return e;
}

// The 300 x 300 grid over the sample's (x, y) bounding box, as the baselines' query points.
std::vector<Vector2d> grid_points(const std::vector<Vec3>& sample) {
  Eigen::AlignedBox2d box;
  for (const Vec3& p : sample) box.extend(p.head<2>());
  std::vector<Vector2d> grid;
  for (int j = 0; j < 300; ++j)
    for (int i = 0; i < 300; ++i) grid.push_back(box.min() + box.sizes().cwiseProduct(Vector2d(i, j) / 299.0));
  return grid;
}

// ---- plain Shepard --------------------------------------------------------------------------
struct Planar {
  const std::vector<Vector2d>* points;
  std::size_t kdtree_get_point_count() const { return points->size(); }
  double kdtree_get_pt(std::size_t i, std::size_t d) const { return (*points)[i][static_cast<Eigen::Index>(d)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};
using PlanarTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Planar>, Planar, 2>;

class PlainShepard {
 public:
  explicit PlainShepard(const std::vector<Vec3>& sample) : sample_(sample) {
    for (const Vec3& p : sample) sites_.push_back(p.head<2>());
    tree_.buildIndex();
    constexpr std::size_t k = 20;
    std::vector<std::uint32_t> index(k);
    std::vector<double> squared(k);
    for (const Vector2d& s : sites_) {
      tree_.knnSearch(s.data(), k, index.data(), squared.data());
      radii_.push_back(std::sqrt(squared[k - 1]));
      largest_ = std::max(largest_, radii_.back());
    }
  }
  double operator()(const Vector2d& q) const {
    std::vector<std::pair<std::uint32_t, double>> within;
    tree_.radiusSearch(q.data(), largest_ * largest_, within, nanoflann::SearchParams());
    double weight = 0, weighted = 0;
    for (const auto& [i, squared] : within) {
      const double w = meshprep::wendland_weight(std::sqrt(squared) / radii_[i]);
      weight += w;
      weighted += w * sample_[i].z();
    }
    return weight > 0 ? weighted / weight : 0;
  }

 private:
  const std::vector<Vec3>& sample_;
  std::vector<Vector2d> sites_;
  Planar adaptor_{&sites_};
  PlanarTree tree_{2, adaptor_, nanoflann::KDTreeSingleIndexAdaptorParams(10)};
  std::vector<double> radii_;
  double largest_ = 0;
};

// ---- linear interpolation on a triangulation of the plane ------------------------------------
// Heights interpolated linearly over the triangles (x, y) of a height field; NaN outside.
class LinearInterpolant {
 public:
  LinearInterpolant(const std::vector<Vec3>& points, std::vector<meshprep::Triangle> triangles)
      : points_(points), triangles_(std::move(triangles)) {
    for (const Vec3& p : points) box_.extend(p.head<2>());
    bucket_size_ = box_.sizes() / kBuckets;
    buckets_.resize(kBuckets * kBuckets);
    for (std::size_t t = 0; t < triangles_.size(); ++t) {  // bucketed by bounding box
      Eigen::AlignedBox2d b;
      for (const std::uint32_t v : triangles_[t]) b.extend(points_[v].head<2>());
      const auto lo = bucket(b.min()), hi = bucket(b.max());
      for (int j = lo.second; j <= hi.second; ++j)
        for (int i = lo.first; i <= hi.first; ++i) buckets_[static_cast<std::size_t>(j * kBuckets + i)].push_back(t);
    }
  }
  double operator()(const Vector2d& q) const {
    const auto [i, j] = bucket(q);
    for (const std::size_t t : buckets_[static_cast<std::size_t>(j * kBuckets + i)]) {
      const Vec3 &a = points_[triangles_[t][0]], &b = points_[triangles_[t][1]], &c = points_[triangles_[t][2]];
      const double area = cross(b - a, c - a);
      const double u = cross(b - lift(q), c - lift(q)) / area, v = cross(c - lift(q), a - lift(q)) / area, w = 1 - u - v;
      constexpr double slack = -1e-12;
      if (u >= slack && v >= slack && w >= slack) return u * a.z() + v * b.z() + w * c.z();
    }
    return std::nan("");
  }

 private:
  static constexpr int kBuckets = 256;
  static Vec3 lift(const Vector2d& q) { return Vec3(q.x(), q.y(), 0); }
  static double cross(const Vec3& a, const Vec3& b) { return a.x() * b.y() - a.y() * b.x(); }
  std::pair<int, int> bucket(const Vector2d& q) const {
    const Vector2d b = (q - box_.min()).cwiseQuotient(bucket_size_);
    return {std::clamp(static_cast<int>(b.x()), 0, kBuckets - 1), std::clamp(static_cast<int>(b.y()), 0, kBuckets - 1)};
  }
  const std::vector<Vec3>& points_;
  std::vector<meshprep::Triangle> triangles_;
  Eigen::AlignedBox2d box_;
  Vector2d bucket_size_;
  std::vector<std::vector<std::size_t>> buckets_;
};

// The planar Delaunay triangulation of the sample: TetGen's 3D Delaunay of the points lifted onto
// the paraboloid z = x^2 + y^2; the hull faces whose outward normal points down (away from the
// lifted points' centroid, an interior point) form its lower hull.
std::vector<meshprep::Triangle> delaunay_triangles(const std::vector<Vec3>& sample) {
  Eigen::AlignedBox2d box;
  for (const Vec3& p : sample) box.extend(p.head<2>());
  tetgenio in, out;
  in.numberofpoints = static_cast<int>(sample.size());
  in.pointlist = new REAL[3 * sample.size()];
  for (std::size_t i = 0; i < sample.size(); ++i) {
    const Vector2d q = (sample[i].head<2>() - box.center()) / box.sizes().maxCoeff();
    in.pointlist[3 * i] = q.x();
    in.pointlist[3 * i + 1] = q.y();
    in.pointlist[3 * i + 2] = q.squaredNorm();
  }
  char switches[] = "Q";
  tetrahedralize(switches, &in, &out);
  Vec3 inside = Vec3::Zero();
  for (int v = 0; v < in.numberofpoints; ++v) inside += Vec3(in.pointlist + 3 * v);
  inside /= in.numberofpoints;
  std::vector<meshprep::Triangle> triangles;
  for (int f = 0; f < out.numberoftrifaces; ++f) {
    const int* t = out.trifacelist + 3 * f;
    const Vec3 a(in.pointlist + 3 * t[0]), b(in.pointlist + 3 * t[1]), c(in.pointlist + 3 * t[2]);
    Vec3 outward = (b - a).cross(c - a);
    if ((inside - a).dot(outward) > 0) outward = -outward;
    if (outward.z() < 0)
      triangles.push_back({static_cast<std::uint32_t>(t[0]), static_cast<std::uint32_t>(t[1]), static_cast<std::uint32_t>(t[2])});
  }
  return triangles;
}

void print_row(const std::string& method, const Errors& e, double seconds) {
  std::printf("| %s | %.2f m | %.0f m | %.3f s |", method.c_str(), e.rms, e.max, seconds);
  if (e.missing > 0) std::printf(" (%zu points outside its domain left out)", e.missing);
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  if (!std::filesystem::exists(kPoints + "jacksboro_10k.xyz")) {
    std::cerr << "bench_reconstruct: " << kPoints << "jacksboro_10k.xyz not found (../shared beside the clone)\n";
    return 2;
  }
  meshprep::ReconstructParams params;
  bool with_adaptive = true;
  for (int a = 1; a < argc; ++a) {
    const std::string flag = argv[a];
    auto value = [&] { return a + 1 < argc ? std::stod(argv[++a]) : throw std::invalid_argument(flag + " needs a value"); };
    if (flag == "--leaf-size") params.fit.leaf_size = static_cast<std::size_t>(value());
    else if (flag == "--neighbors") params.fit.neighbors = static_cast<std::size_t>(value());
    else if (flag == "--enlargement") params.fit.enlargement = value();
    else if (flag == "--variation-threshold") {
      params.fit.variation_threshold = value();
      params.fit.variation_percentile = -1;
    } else if (flag == "--variation-percentile") params.fit.variation_percentile = value();
    else if (flag == "--variation-growth") params.fit.variation_growth = value();
    else if (flag == "--quadratic") params.fit.polynomial = meshprep::HeightMapPolynomial::quadratic;
    else if (flag == "--no-adaptive") with_adaptive = false;
    else {
      std::cerr << "bench_reconstruct: unknown option " << flag << "\n";
      return 2;
    }
  }
  const std::vector<Vec3> sample = meshprep::read_points(kPoints + "jacksboro_10k.xyz").points;
  std::vector<Vec3> held_out;
  {
    std::set<std::pair<long long, long long>> in_sample;
    for (const Vec3& p : sample) in_sample.insert({std::llround(p.x() * 1000), std::llround(p.y() * 1000)});
    for (const Vec3& p : meshprep::read_points(kPoints + "jacksboro_grid.xyz").points)
      if (!in_sample.count({std::llround(p.x() * 1000), std::llround(p.y() * 1000)})) held_out.push_back(p);
  }
  std::printf("%zu samples, %zu held-out grid points; leaf size %zu, %zu neighbours, enlargement %.2f\n\n",
              sample.size(), held_out.size(), params.fit.leaf_size, params.fit.neighbors, params.fit.enlargement);
  std::printf("| method | RMS | max | 90k-vertex mesh |\n| --- | --- | --- | --- |\n");
  std::vector<double> predicted(held_out.size());
  const std::vector<Vector2d> grid = grid_points(sample);

  {  // meshprep: the height above the reference plane, taken along the vertical (as the test does)
    const meshprep::PartitionOfUnity pu(sample, params.fit);
    const Vec3 normal = pu.frame().normal();
    for (std::size_t i = 0; i < held_out.size(); ++i) {
      const Vec3 local = pu.frame().to_local(held_out[i]);
      const Vec3 surface = pu.surface_point(local.x(), local.y());
      predicted[i] = held_out[i].z() + (surface - held_out[i]).dot(normal) / std::abs(normal.z());
    }
    const double seconds = median_seconds(5, [&] { meshprep::reconstruct_surface(sample, params); });
    print_row("meshprep partition of unity (Duchon r^2.5 patches)", errors(held_out, predicted), seconds);
    std::vector<double> sigma = pu.patch_variation();
    std::sort(sigma.begin(), sigma.end());
    auto at = [&](double q) { return sigma[static_cast<std::size_t>(q * static_cast<double>(sigma.size() - 1))]; };
    std::fprintf(stderr, "patch sigma: median %.4f, p90 %.4f, p99 %.4f, max %.4f; %zu of %zu patches grown\n", at(0.5),
                 at(0.9), at(0.99), sigma.back(), pu.grown_patches(), pu.patches());
  }
  {
    double seconds = median_seconds(5, [&] {
      const PlainShepard shepard(sample);
      double sum = 0;
      for (const Vector2d& q : grid) sum += shepard(q);
      benchmark_sink(sum);
    });
    const PlainShepard shepard(sample);
    for (std::size_t i = 0; i < held_out.size(); ++i) predicted[i] = shepard(held_out[i].head<2>());
    print_row("plain Shepard (Wendland, raw heights), baseline", errors(held_out, predicted), seconds);
  }
  {
    const double seconds = median_seconds(5, [&] {
      const LinearInterpolant linear(sample, delaunay_triangles(sample));
      double sum = 0;
      for (const Vector2d& q : grid) sum += linear(q);  // NaN at grid corners outside the hull
      benchmark_sink(sum);
    });
    const LinearInterpolant linear(sample, delaunay_triangles(sample));
    for (std::size_t i = 0; i < held_out.size(); ++i) predicted[i] = linear(held_out[i].head<2>());
    print_row("Delaunay linear interpolation (TetGen lifting), baseline", errors(held_out, predicted), seconds);
  }
  // The meshes themselves, linear between their vertices: what a user gets in the file.
  for (const bool adaptive : {false, true}) {
    if (adaptive && !with_adaptive) continue;
    const auto start = std::chrono::steady_clock::now();
    const meshprep::TriangleSoup mesh = adaptive ? meshprep::reconstruct_adaptive(sample, {params, {}}).mesh
                                                 : meshprep::reconstruct_surface(sample, params).mesh;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const LinearInterpolant linear(mesh.points, mesh.triangles);
    for (std::size_t i = 0; i < held_out.size(); ++i) predicted[i] = linear(held_out[i].head<2>());
    print_row(std::string("meshprep ") + (adaptive ? "--adaptive" : "300 x 300") + " mesh (" +
                  std::to_string(mesh.triangles.size()) + " faces), linear between vertices",
              errors(held_out, predicted), seconds);
  }
  return 0;
}
