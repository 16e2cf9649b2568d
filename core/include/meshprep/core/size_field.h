#pragma once
/// \file size_field.h
/// The edge length a mesh aims at, anywhere in space: h(x). The surface's remeshing (preprocess)
/// and the tets (fem) read the same field; the enhancement builds it (preprocess/src/enhance/
/// sizing_field.h, the user's own demands from user_size_demands.h) from the demands a surface
/// and its user make: a length wanted at a point (the user's size, the curvature, the thickness
/// across a wall) or over a region, and a grading.
///
/// Grading: h is the largest function under every demand whose gradient is at most g = grading - 1,
/// h(x) = min over demands s of (h_s + g |x - s|): the closed-form solution of gradient limiting,
/// |grad h| <= g (Persson, "Mesh size functions for implicit geometries and PDE-based gradient
/// limiting", Eng. with Computers 22, 2006, eq. 7). An element of size h(x) and its neighbour, one
/// element away, then differ in size by at most (1 + g) = the grading. The result is clamped to
/// [shortest, longest]; deterministic (no order dependence: a minimum).

#include "meshprep/core/mesh.h"

#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace meshprep {

/// A length: absolute, or a fraction of the bounding-box diagonal ("2%" on the command line and
/// in the configuration file).
struct Length {
  double value = 0;
  bool relative = false;
  /// value, or value * diagonal when relative.
  double resolved(double diagonal) const { return relative ? value * diagonal : value; }
};

/// "0.5" (absolute) or "2%" (of the diagonal). \throws InvalidInput "<what>: expected a positive
/// length or a percentage of the diagonal such as 2%, not '<text>'".
Length parse_length(const std::string& text, const std::string& what);
/// "0.5", "2%".
std::string length_text(const Length& length);

/// A box [lo, hi] or a ball (center, radius) of space, where a size holds.
struct SizeRegion {
  enum class Shape { box, sphere };
  Shape shape = Shape::box;
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  ///< a box's corners (lo <= hi)
  Vec3 center = Vec3::Zero();                 ///< a ball's
  double radius = 0;
  Length size;  ///< the elements' size inside it

  /// The distance from x to the region (0 inside).
  double distance(const Vec3& x) const;
};

/// What the user asks of the element size. The defaults ask nothing: the surface's own demands
/// (its density, curvature and thickness) make the field.
struct SizeParams {
  std::optional<Length> size;      ///< h everywhere no finer demand holds (unset: the input's density)
  std::optional<Length> size_min;  ///< no demand goes below it
  std::optional<Length> size_max;  ///< nothing is longer
  /// Neighbouring elements' sizes differ by at most this ratio (>= 1). Unset (automatic):
  /// kSizeGrading once any size is set, else the enhancement keeps its own field's kSurfaceGrading.
  std::optional<double> grading;
  /// Elements per 2 pi of turning on a curved surface (Gmsh's Mesh.MeshSizeFromCurvature): a circle
  /// of radius r gets edges of 2 pi r / N. Unset: only the fidelity bound's chord limits them.
  std::optional<double> curvature_points;
  /// At least this many elements across a thin wall (its thickness over this); unset: 1.
  std::optional<double> thickness_layers;
  /// The size on the faces of a named patch (--size NAME=LENGTH): a patch's name, matched without
  /// regard to case, to its size. A size refines: where the field asks for less, that holds.
  std::map<std::string, Length> patch_sizes;
  /// Boxes and balls with a size of their own (the configuration's size.regions); refine too.
  std::vector<SizeRegion> regions;

  /// The user asked for a size (any field but the grading set): the tets then follow the field too.
  bool any_set() const {
    return size || size_min || size_max || curvature_points || thickness_layers || !patch_sizes.empty() ||
           !regions.empty();
  }
  /// The grading to use: the one set, else kSizeGrading when a size is set, else kSurfaceGrading.
  double grading_used() const;
};

/// The automatic grading of a field the user asked for (Gmsh's and Netgen's usual 1.3).
inline constexpr double kSizeGrading = 1.3;
/// The automatic grading of the enhancement's own field when no size is set: Persson's gradation
/// of 1.5 for mesh-size functions, the enhancement's since it remeshes. 1.3 there gave fewer faces
/// under 20 deg on 23 of the 41 shared meshes it remeshes (worse on 2) for 1.23x the faces and
/// 1.19x the time, and let the knife-edge stage thin a plate thinner than the fidelity bound by 7 %
/// of its volume (bench/RESULTS.md, "Size field"): not the default until that is guarded.
inline constexpr double kSurfaceGrading = 1.5;

struct SizeDemand {
  Vec3 point;
  double length = 0;
};

/// A triangle's own density: the mean of its edges, at its centroid.
inline SizeDemand face_density_demand(const Vec3& a, const Vec3& b, const Vec3& c) {
  return {(a + b + c) / 3.0, ((b - a).norm() + (c - b).norm() + (a - c).norm()) / 3};
}

/// A length asked for over a whole region of space (h_s + g * distance to the region outside it).
struct RegionDemand {
  SizeRegion region;  ///< its size is not read: `length` is the resolved one
  double length = 0;
};

class SizeField {
 public:
  /// `longest`: the length where no demand asks for less (> 0, finite); `shortest` the floor
  /// (in [0, longest]); `grading` >= 1. Demands at or over `longest` change nothing and are dropped.
  /// \throws InvalidInput when a bound or the grading is out of range.
  /// `regions` ask for their length over a volume, graded outside it as a point's demand is.
  SizeField(const std::vector<SizeDemand>& demands, double longest, double grading, double shortest = 0,
            std::vector<RegionDemand> regions = {});
  ~SizeField();
  SizeField(SizeField&&) noexcept;
  SizeField& operator=(SizeField&&) noexcept;

  /// h(x) (times the scale, at x minus the offset).
  double operator()(const Vec3& x) const;
  /// The field with no demand: `longest`; the demands' smallest, clamped (times the scale).
  double longest() const { return longest_ * scale_; }
  double shortest() const { return shortest_demand_ * scale_; }
  double grading() const { return 1 + slope_; }
  std::size_t demands() const;
  std::size_t regions() const { return regions_.size(); }
  /// Every length times `factor` (> 1: coarser).
  void scale(double factor) { scale_ *= factor; }
  double scale_factor() const { return scale_; }
  /// The field moved by `offset`: h(x) becomes h(x - offset) (built on a surface shifted next to
  /// the origin, core/origin_shift.h, and read where the surface is shifted back).
  void move(const Vec3& offset) { offset_ += offset; }

 private:
  struct Levels;
  std::unique_ptr<Levels> levels_;
  std::vector<RegionDemand> regions_;
  double longest_ = 0, floor_ = 0, slope_ = 0, shortest_demand_ = 0, scale_ = 1;
  Vec3 offset_ = Vec3::Zero();
};

}  // namespace meshprep
