#pragma once
/// \file enhance.h
/// Statistical triangle enhancement: vertices move on the surface, and a few edges flip, so that
/// the bad tail of the triangle-quality distribution disappears while the surface stays where it
/// was (the paper's Figure 6 stage, whose algorithm the paper omits; docs/enhancement.md has the
/// design and the measurements).
///
/// Each round:
/// 1. The statistic. q = 1 / radius_ratio of every face (1 equilateral, 0 degenerate); its mean mu
///    and standard deviation s; the tail threshold tau = mu - k s. A face's weight is
///    w = 1 + gamma (tau - q) / s below tau (and at least 1 + gamma when its smallest angle is
///    under the target), 1 elsewhere.
/// 2. Topology: flips of interior non-feature edges that raise the smaller of the two faces'
///    smallest angles, when the two new faces are nearly coplanar (dihedral under the flip
///    threshold) and the new diagonal stays as close to the reference as the old one (or within
///    the deviation bound); then valence-3 vertices whose three faces make a better one are
///    removed (at most 1 % of the faces' count of vertices: the face count stays within 2 %).
/// 3. One Ceres least-squares problem over all movable vertices: a vertex on no feature has two
///    unknowns, its coordinates in its tangent plane, lifted onto a quadratic height map of the
///    surface around it; a vertex on a crease or on the boundary has one, along its line; corners
///    stay. Residuals: w (1/eta - 1) per face, eta = 4 sqrt(3) A / (|ab|^2 + |bc|^2 + |ca|^2) the
///    mean ratio (automatic differentiation; the signed area in the face's own normal direction is
///    a barrier against fold-overs), and a fidelity residual per face, sqrt(lambda) times the
///    distance of its centroid to the reference's tangent plane there, over the mean edge length.
/// 4. Every moved vertex is put back onto the reference (its closest point; its own feature line
///    for crease and boundary vertices). Moves that turn a face by more than 60 degrees, carry a
///    face farther than the deviation bound from the reference, or make the surface cross itself
///    are taken back.
/// The rounds stop when neither the fraction of faces under the target angle nor the 5th
/// percentile of q improves; the best round is kept.

#include "meshprep/core/mesh.h"

#include <cstddef>
#include <functional>

namespace meshprep {

struct EnhanceParams {
  std::size_t iterations = 10;          ///< rounds at most (each: statistic, flips, Ceres, projection)
  /// A face's centroid may not move farther than this from the reference (relative to the
  /// reference's bounding-box diagonal) unless it already was.
  double max_deviation = 2e-3;
  double target_min_angle_deg = 20;     ///< faces under this smallest angle are always in the tail
  double feature_angle_deg = 45;        ///< an edge with a larger dihedral angle is a crease; 180 = none
  bool flips = true;
  /// The statistic's constants; defaults fitted by bench/tune_enhance (see enhance_defaults.h).
  double tail_k;
  double tail_weight;                   ///< gamma
  double fidelity_weight;               ///< lambda
  double flip_dihedral_deg;             ///< largest dihedral angle across a flipped edge
  std::function<void(double)> progress; ///< called with the fraction done
  EnhanceParams();
};

/// Shape of a mesh's triangle-quality distribution (q = 1 / radius_ratio).
struct QualityTail {
  double mean_q = 0, stddev_q = 0;
  double q_p05 = 0;                     ///< 5th percentile of q
  double under_target_fraction = 0;     ///< faces with smallest angle under the target
  double min_angle_deg = 0;             ///< smallest angle of the mesh
};

struct EnhanceResult {
  std::size_t rounds = 0;               ///< rounds run (the last may have been discarded)
  std::size_t kept_round = 0;           ///< the round whose mesh was kept (0 = the input)
  std::size_t flips = 0;
  std::size_t removed_vertices = 0;     ///< of valence 3 (two faces each)
  std::size_t line_vertices = 0;        ///< on a crease or the boundary: slid along it
  std::size_t fixed_vertices = 0;       ///< corners and non-manifold vertices: kept
  std::size_t undone_moves = 0;         ///< vertex moves taken back by the guards
  QualityTail before, after;
  double seconds = 0;
};

/// Enhance `mesh` in place. `reference` is the surface to stay on (the original mesh); nullptr
/// means the input itself. \throws InvalidInput if params are out of range or the mesh is empty.
EnhanceResult enhance(TriMesh& mesh, const TriangleSoup* reference, const EnhanceParams& params = {});

}  // namespace meshprep
