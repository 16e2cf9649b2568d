#pragma once
/// \file smooth.h
/// Denoising a surface mesh without shrinking it and without rounding off its features.
///
/// The paper's Section 5 smoothing (method Rbf): each vertex moves onto the local surface of its
/// neighbours in their PCA tangent frame: the height map of local_height_map.h, the simplifier's
/// placement step. Here the height map is a cubic fitted to the vertex and its neighbours (4
/// rings) with Gaussian weights of the distance, the lambda -> infinity limit of the weighted
/// thin-plate smoothing spline (thin_plate_spline.h; a finite `smoothing` gives the spline). It
/// reproduces planes, quadrics and cubics exactly but does not chase the neighbours' own noise.
/// The vertex is put on that surface below its point moved halfway to its 1-ring's centroid, which
/// evens out the triangles without leaving the surface. docs/smoothing.md has the measurements
/// behind every default.
///
/// Features: an edge whose bilaterally filtered face normals differ by more than the feature angle
/// is a crease, unless one surface over both of its sides fits them about as well as the surface
/// vertices' fits (then the crease was noise). A vertex on no crease is fitted to the neighbours
/// reached without crossing one (the same side of any nearby feature); a vertex on exactly two
/// creases lies on a feature line and is projected, in turn, onto the surfaces of its two sides
/// (their intersection: the edge stays sharp); a vertex on one or three or more creases is a corner
/// and stays. Boundary vertices stay. Moves that make the surface cross itself are taken back
/// after each iteration.
///
/// Adapting to the mesh (`adaptive`, the default): a fit's error is the noise it leaves plus its
/// bias where it cannot follow the surface, and on a coarse mesh the bias of 4 rings is larger than
/// the noise. Each vertex gets two proposals, the 4-ring fit and a narrow one (24 nearest sites,
/// Gaussian of 1.25 edges). The noise level s comes from the mesh: the narrow fit's moves less their
/// 1-ring mean (white noise survives, a smooth bias does not), median, times a conservative 0.6.
/// Each proposal's bias is estimated from its moves' 1-ring mean and from where the two fits
/// disagree; the vertex takes alpha x the proposal with the least expected squared error, alpha
/// minimising it, or stays when staying (error s^2) is better. A safety net caps every move at 2 s
/// along the normal and 3 s in all. A noise-free mesh (s = 0) does not move.
///
/// All vertices move at once (Jacobi): parallel, and the same result on any thread count.
/// Taubin (lambda | mu = 0.5 | -0.53 on the uniform Laplacian) and Laplace (OpenMesh's Jacobi
/// Laplace smoother) are in-tree baselines.

#include "meshprep/core/mesh.h"
#include "meshprep/core/taken_back.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <functional>
#include <limits>
#include <optional>

namespace meshprep {

enum class SmoothMethod { Rbf, Taubin, Laplace };

struct SmoothParams {
  SmoothMethod method = SmoothMethod::Rbf;
  std::size_t iterations = 1;
  std::size_t neighbors = 80;  ///< Rbf: the N nearest neighbours on the vertex's side (4 rings), >= 13
  /// Rbf: lambda of the weighted thin-plate smoothing spline; infinity (the default) is its limit,
  /// the weighted least-squares cubic; 0 interpolates.
  double smoothing = std::numeric_limits<double>::infinity();
  double relaxation = 0.5;        ///< Rbf: fraction of the way to the 1-ring centroid, in [0, 1]; 0 = along the normal only
  double feature_angle_deg = 45;  ///< Rbf: a crease is an edge with a larger dihedral angle; 180 = none
  /// Rbf: how far each vertex moves, and onto which of two fits (4 rings, or about 2), is chosen
  /// from the noise the mesh shows (see above); false moves every vertex onto its 4-ring fit.
  bool adaptive = true;
  /// Closed meshes: offset the result along its normals so the enclosed volume is the input's.
  bool preserve_volume = false;
  std::function<void(double)> progress;  ///< called with the fraction done
};

struct SmoothResult {
  std::size_t iterations = 0;
  std::size_t feature_line_vertices = 0;  ///< on exactly two creases (last iteration)
  std::size_t corner_vertices = 0;        ///< on one or three or more creases: kept
  std::size_t noise_crease_vertices = 0;  ///< on creases one surface explains (noise): smoothed
  std::size_t boundary_vertices = 0;      ///< kept
  std::size_t unfitted_vertices = 0;      ///< too few neighbours on their side to fit: kept
  std::size_t undone_vertices = 0;        ///< moves taken back because the surface crossed itself
  std::size_t not_moved_vertices = 0;     ///< adaptive: no fit promised less error than staying (last iteration)
  double noise_level = 0;                 ///< adaptive: the noise level the moves assumed (mesh units; last iteration)
  double max_displacement = 0;            ///< of a vertex from input to output
  std::optional<double> volume_before, volume_after;  ///< closed meshes
  /// Intersecting face pairs of the input, when the method had to count them (Rbf: its guard,
  /// when a step left the surface crossing itself).
  std::optional<std::size_t> input_self_intersections;
  double seconds = 0;
  std::vector<TakenBack> taken_back;  ///< moves put back because the surface crossed itself
};

/// Smooth `mesh` in place. \throws InvalidInput if params are out of range.
SmoothResult smooth(TriMesh& mesh, const SmoothParams& params = {});

/// The run as `meshprep smooth --json` writes it, in this order: method ("rbf", "taubin" or
/// "laplace"), iterations; for Rbf its settings (neighbors, smoothing: "inf" for interpolation,
/// relaxation, feature_angle_deg, adaptive, noise_level) and vertex counts (noise_crease_vertices,
/// vertices_kept {corners, boundary, unfitted, undone_for_self_intersections, not_moved},
/// feature_line_vertices); then
/// preserve_volume, volume_before, volume_after, volume_change_relative (null on an open mesh),
/// max_displacement, guards_taken_back (json_values.h), time_seconds. The pipeline's stage record picks from it.
nlohmann::ordered_json to_json(const SmoothResult& result, const SmoothParams& params);

}  // namespace meshprep
