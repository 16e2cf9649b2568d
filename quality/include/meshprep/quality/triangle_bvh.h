#pragma once
/// \file triangle_bvh.h
/// A bounding-volume hierarchy (axis-aligned boxes, median split) over the triangles of a soup,
/// for closest-point queries and overlap searches.

#include "meshprep/core/mesh.h"
#include "meshprep/core/soup_view.h"

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace meshprep {

using Box3 = Eigen::AlignedBox3d;

/// Bounding box of the vertices the faces of `soup` use (empty box if there is no face).
Box3 bounding_box(const SoupView& soup);

/// Closest point on triangle (a, b, c) to p (exact, Ericson's region classification).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Closest point on segment [a, b] to p (a if the segment has no length).
Vec3 closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b);

/// Where the ray origin + t direction crosses triangle (a, b, c): t, or infinity if it does not
/// (Moeller & Trumbore 1997; parallel rays and crossings at t <= 0 count as none).
double ray_triangle(const Vec3& origin, const Vec3& direction, const Vec3& a, const Vec3& b, const Vec3& c);

class TriangleBvh {
 public:
  /// Builds the hierarchy over every triangle of `soup` (a view: what it sees, a TriangleSoup or a
  /// MeshSoupView, must outlive the BVH and keep its points where they were when it was built).
  explicit TriangleBvh(const SoupView& soup);
  TriangleBvh(TriangleSoup&&) = delete;  // a temporary would not outlive it
  TriangleBvh(MeshSoupView&&) = delete;

  struct Hit {
    std::size_t face = 0;
    Vec3 point = Vec3::Zero();
    double squared_distance = 0;
  };

  /// Closest point of the surface to p. \pre the soup has at least one triangle.
  Hit closest_point(const Vec3& p) const;

  /// Whether some triangle comes within sqrt(squared_radius) of p: the same answer as
  /// `closest_point(p).squared_distance <= squared_radius`, but the search stops at the first such
  /// triangle and never opens a box farther than the radius.
  bool reaches_within(const Vec3& p, double squared_radius) const;

  struct RayHit {
    double distance = 0;  ///< along the direction (a unit direction gives lengths); infinity: none
    std::size_t face = 0;
  };
  /// The nearest crossing of the ray origin + t direction (t > 0) with a triangle other than
  /// `skip_face` (Moeller & Trumbore's test per triangle; a ray in a triangle's plane does not
  /// cross it).
  RayHit first_hit(const Vec3& origin, const Vec3& direction, std::size_t skip_face) const;
  /// Calls `visit(face)` for every triangle whose box overlaps `box`.
  void for_each_overlapping(const Box3& box, const std::function<void(std::size_t)>& visit) const;

  /// Calls `visit(i, j)` once for every pair of triangles i < j whose boxes overlap and that have
  /// no corner (point index) in common: the hierarchy traversed against itself (pairs of nodes, not
  /// a query from the root per triangle: several times fewer box tests). Two nodes whose triangles
  /// all have one corner in common are passed over whole, so the triangles around one vertex (a
  /// fan: their boxes all overlap at it) cost nothing here. Runs in parallel: `visit` must be
  /// thread-safe, and the order of the calls is unspecified.
  void for_each_overlapping_pair_apart(const std::function<void(std::size_t, std::size_t)>& visit) const;

  /// The surface the hierarchy was built over.
  const SoupView& surface() const { return soup_; }

 private:
  /// A box in single precision, its bounds rounded outwards: it holds the double box it was made
  /// from, so every test against it is a filter the exact test behind it settles. Half the memory
  /// of a Box3 (at 10 M faces the hierarchy was the largest array of a quality report).
  struct FloatBox {
    std::array<float, 3> min{}, max{};
    static FloatBox around(const Box3& box);
    FloatBox merged(const FloatBox& other) const;
    Box3 widened() const;  ///< as doubles (exact)
    // (Inline: the closest-point search calls this twice a node.)
    bool intersects(const FloatBox& other) const {
      for (int k = 0; k < 3; ++k)
        if (!(min[k] <= other.max[k] && other.min[k] <= max[k])) return false;
      return true;
    }
    /// As Eigen's AlignedBox::squaredExteriorDistance.
    double squared_exterior_distance(const Vec3& p) const {
      double sum = 0;
      for (int k = 0; k < 3; ++k) {
        const double low = min[k], high = max[k];
        if (low > p[k]) sum += (low - p[k]) * (low - p[k]);
        else if (p[k] > high) sum += (p[k] - high) * (p[k] - high);
      }
      return sum;
    }
  };
  /// 44 bytes. An inner node's left child is the next node (the nodes are in preorder).
  struct Node {
    FloatBox box;
    std::uint32_t first_or_right = 0;  ///< leaf: first index into order_; inner node: its right child
    std::uint32_t count = 0;           ///< leaf: number of triangles; 0 for an inner node
    std::array<std::uint32_t, 3> common{};  ///< corners every triangle below has, kNoCorner after the last
  };
  static constexpr std::uint32_t kNoCorner = ~std::uint32_t(0);
  std::uint32_t build(std::uint32_t index, std::uint32_t begin, std::uint32_t end, const std::vector<Vec3>& centroids,
                      int depth);
  void overlapping_pairs(std::uint32_t a, std::uint32_t b, int depth,
                         const std::function<void(std::size_t, std::size_t)>& visit) const;

  SoupView soup_;
  std::vector<FloatBox> boxes_;      ///< per triangle
  std::vector<std::uint32_t> order_;  ///< triangle indices, grouped by leaf
  std::vector<Node> nodes_;           ///< nodes_[0] is the root
};

}  // namespace meshprep
