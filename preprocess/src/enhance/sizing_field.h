#pragma once
// The edge length the remeshing (adaptive_remeshing.h) aims at, anywhere on the surface: the
// surface's own demands, not the input's tessellation (a CAD export's needles say nothing about
// the part).

#include "enhance/surface_constraints.h"

#include "meshprep/core/mesh.h"
#include "meshprep/core/size_field.h"

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace meshprep::detail {

struct SizingRules {
  /// Absolute distance a chord may stray from a curved surface: the curvature's limit on the
  /// length is the chord whose sagitta this is (L = sqrt(8 r tolerance)). Also the shortest length.
  double chord_tolerance = 0;
  /// At most this many faces (estimated over the input): the field is scaled up uniformly when it
  /// asks for more.
  std::size_t max_faces = 0;
  /// The user's sizes, curvature and thickness rules and the grading (core/size_field.h).
  SizeParams size;
  /// A feature edge between two corners, which no remeshing removes, asks for its own length, so
  /// that the faces around it grade up from it (the tets next to a CAD part's short edges then can
  /// reach the goal: example014 11.8 -> 15.1 deg, text_on_cube 13.1 -> 15.0).
  bool grade_from_corner_edges = true;
  /// Lengths asked where an earlier remeshing made the surface cross itself (two sheets closer
  /// than its faces were long): held like any other demand, graded around.
  std::vector<SizeDemand> crossing_demands;
};

/// The smallest of: the base length (the user's size, else the equilateral edge that tiles the
/// input's area with its own number of faces: the density the user chose), at most the user's
/// size_max; at each interior edge that is no crease, the chord of the curvature's tolerance (the
/// curvature is the edge's dihedral angle over the width of its two faces: a faceted cylinder's
/// strips give 1 / r), and with curvature_points N, 2 pi / (N curvature), sampled along the edge;
/// at each feature edge between two corners no shorter than the chord tolerance, its length
/// (grade_from_corner_edges);
/// and over each face of a closed mesh, the local thickness (the distance along its inward normal
/// to the surface across: a plate needs edges no longer than it is thick, or its tets are flat)
/// over thickness_layers, sampled at the centroids of the face's quarters, and theirs, until they
/// are no longer than it; the user's patch sizes over their patches' faces and the user's regions
/// (core/size_field.h); and the crossing demands of an earlier remeshing. Each demand holds at
/// its own point and relaxes with distance by the grading, never under size_min (else the chord
/// tolerance, or the user's smallest patch or region size if less). Demands sit where they are
/// measured, not at the corners of a needle that may be far away.
class SizingField {
 public:
  /// `mesh` is the input (on its reference).
  SizingField(const TriMesh& mesh, const SurfaceConstraints& constraints, const SizingRules& rules);
  ~SizingField();
  SizingField(const SizingField&) = delete;
  SizingField& operator=(const SizingField&) = delete;

  /// The target edge length at x.
  double operator()(const Vec3& x) const { return (*field_)(x); }
  /// The field itself (the tets may follow it too).
  std::shared_ptr<SizeField> field() const { return field_; }

  double base_length() const { return field_->longest(); }
  double shortest() const { return field_->shortest(); }
  /// Faces the field asks for over the input (after the cap).
  std::size_t estimated_faces() const { return estimated_faces_; }
  bool capped() const { return field_->scale_factor() > 1; }
  /// Demands the corner edges made (grade_from_corner_edges): none, and the field is as without it.
  std::size_t corner_edge_demands() const { return corner_edge_demands_; }
  /// Every length times `factor` (> 1: fewer faces).
  void coarsen(double factor) { field_->scale(factor); }

 private:
  using Corners = std::array<Vec3, 3>;
  /// The thickness under triangle `c` (part of input face `face`) at its centroid, as a demand;
  /// then, if the triangle is longer than that and not much thinner than its parent piece, the
  /// same for its four quarters (`parent_thickness` 0: a whole face).
  void sample_thickness(const TriangleBvh& bvh, const Corners& c, const Vec3& inward, std::size_t face, double floor,
                        double layers, std::size_t most_demands, double parent_thickness);
  /// Faces the field asks for over triangle (a, b, c), cut into quarters until its pieces
  /// are no longer than the field there or `most_evaluations` is reached.
  double faces_over(const Vec3& a, const Vec3& b, const Vec3& c, std::size_t& evaluations, std::size_t most_evaluations) const;

  std::vector<SizeDemand> demands_;
  double base_ = 0;
  std::shared_ptr<SizeField> field_;
  std::size_t estimated_faces_ = 0;
  std::size_t corner_edge_demands_ = 0;
};

}  // namespace meshprep::detail
