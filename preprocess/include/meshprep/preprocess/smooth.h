#pragma once
/// \file smooth.h
/// Denoising a surface mesh without shrinking it and without rounding off its features.
///
/// The paper's Section 5 smoothing (method Rbf): each vertex moves onto the RBF surface through
/// its N nearest neighbours, in their PCA tangent frame: the local height map of
/// local_height_map.h, the simplifier's placement step. Here the height map is the thin-plate
/// *smoothing* spline with a quadratic polynomial (thin_plate_spline.h): it reproduces planes
/// and quadrics exactly but does not chase the neighbours' own noise. docs/smoothing.md has the
/// measurements behind every default.
///
/// Features: an edge whose bilaterally filtered face normals differ by more than the feature angle
/// is a crease. A vertex on no crease is fitted to the neighbours reached without crossing one
/// (the same side of any nearby feature) and moves along its normal; a vertex on exactly two
/// creases lies on a feature line and is projected, in turn, onto the surfaces of its two sides
/// (their intersection: the edge stays sharp); a vertex on one or three or more creases is a
/// corner and stays. Boundary vertices stay. Moves that make the surface cross itself are taken
/// back after each iteration.
///
/// All vertices move at once (Jacobi): parallel, and the same result on any thread count.
/// Taubin (lambda | mu = 0.5 | -0.53 on the uniform Laplacian) and Laplace (OpenMesh's Jacobi
/// Laplace smoother) are in-tree baselines.

#include "meshprep/core/mesh.h"

#include <cstddef>
#include <functional>
#include <optional>

namespace meshprep {

enum class SmoothMethod { Rbf, Taubin, Laplace };

struct SmoothParams {
  SmoothMethod method = SmoothMethod::Rbf;
  std::size_t iterations = 2;
  std::size_t neighbors = 40;     ///< Rbf: the N nearest neighbours on the vertex's side (3 rings), >= 8
  double smoothing = 1;           ///< Rbf: lambda of the thin-plate smoothing spline; 0 interpolates
  double feature_angle_deg = 45;  ///< Rbf: a crease is an edge with a larger dihedral angle; 180 = none
  /// Closed meshes: offset the result along its normals so the enclosed volume is the input's.
  bool preserve_volume = false;
  std::function<void(double)> progress;  ///< called with the fraction done
};

struct SmoothResult {
  std::size_t iterations = 0;
  std::size_t feature_line_vertices = 0;  ///< on exactly two creases (last iteration)
  std::size_t corner_vertices = 0;        ///< on one or three or more creases: kept
  std::size_t boundary_vertices = 0;      ///< kept
  std::size_t unfitted_vertices = 0;      ///< too few neighbours on their side to fit: kept
  std::size_t undone_vertices = 0;        ///< moves taken back because the surface crossed itself
  double max_displacement = 0;            ///< of a vertex from input to output
  std::optional<double> volume_before, volume_after;  ///< closed meshes
  /// Intersecting face pairs of the input, when the method had to count them (Rbf: its guard).
  std::optional<std::size_t> input_self_intersections;
  double seconds = 0;
};

/// Smooth `mesh` in place. \throws InvalidInput if params are out of range.
SmoothResult smooth(TriMesh& mesh, const SmoothParams& params = {});

}  // namespace meshprep
