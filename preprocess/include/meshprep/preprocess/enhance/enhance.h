#pragma once
/// \file enhance.h
/// Statistical triangle enhancement: vertices move on the surface, and a few edges flip, so that
/// the bad tail of the triangle-quality distribution disappears while the surface stays where it
/// was (the paper's Figure 6 stage, whose algorithm the paper omits; docs/enhancement.md has the
/// design and the measurements).
///
/// Each round: (1) the statistic: q = 1 / radius_ratio per face, tail threshold tau = mean - k std,
/// weights w = 1 + gamma (tau - q) / std below tau (at least 1 + gamma under the target angle);
/// (2) flips and collapses that mend what moving cannot, never across a feature, never away from
/// the surface; (3) one Ceres problem: w (1/eta - 1) per face (eta the mean ratio, automatic
/// derivatives, a fold-over barrier) plus a face-fidelity residual, two unknowns per vertex on its
/// tangent-plane height map, one along a crease or the boundary, corners fixed; (4) back onto the
/// reference, a least-squares normal fit, and guards that take back moves which turn a face, leave
/// the deviation bound in either direction, or make the surface cross itself. The rounds stop when
/// the distribution stops improving; the best is kept.

#include "meshprep/core/deadline.h"
#include "meshprep/core/mesh.h"
#include "meshprep/core/size_field.h"
#include "meshprep/core/taken_back.h"
#include "meshprep/preprocess/patches/patches.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>

namespace meshprep {

/// When the enhancement remeshes first (adaptive_remeshing.h): always, never, or when the input
/// lies on its reference (none given, or the input itself) and has more than
/// EnhanceParams::kRemeshAbove of its faces under the target angle.
enum class EnhanceRemesh { Auto, On, Off };

/// The automatic time limit, floor + per face (of the input, or of the remeshing's sizing field
/// when it asks for more). On the 44 parts of the shared data that reach it, the enhancement took
/// 12-635 us per face (median 265), but on one, cheese (18,000 faces of 0.2-degree slivers, ten
/// rounds of 1,400 flips each), 1.9-2.3 ms. So 1 ms per face: every part but that one uses at most
/// 39 % of its limit (the VM's speed drifts up to 2x); the cheese's rounds start up to its limit
/// (28 s) and its run ends after the round under way (bench/RESULTS.md, "Time budgets").
inline constexpr double kEnhanceTimeLimitFloorSeconds = 10;
inline constexpr double kEnhanceTimeLimitPerFaceSeconds = 1e-3;
/// kEnhanceTimeLimitFloorSeconds + kEnhanceTimeLimitPerFaceSeconds * faces (times kAutomaticTimeLimitScale).
double automatic_enhance_time_limit(std::size_t faces);

struct EnhanceParams {
  std::size_t iterations = 10;          ///< rounds at most (each: statistic, flips, Ceres, projection)
  /// A face's centroid may not move farther than this from the reference (relative to the
  /// reference's bounding-box diagonal) unless it already was. Unset: the input's own Hausdorff
  /// distance from the reference (sampled as the quality report does, rounded up to two digits),
  /// so that the enhancement is no less faithful than its input, at most kLargestAutoDeviation, and that when the
  /// input lies on its reference (no reference given, or the mesh itself).
  std::optional<double> max_deviation;
  /// The automatic bound's largest value, and its value on the reference: the bound the statistic's
  /// constants were tuned with (enhance_defaults.h).
  static constexpr double kLargestAutoDeviation = 2e-3;
  double target_min_angle_deg = 20;     ///< faces under this smallest angle are always in the tail
  /// An edge with a larger dihedral angle is a crease; 180 = none. Patch borders are features too.
  double feature_angle_deg = kDefaultCreaseAngleDeg;
  bool flips = true;
  EnhanceRemesh remesh = EnhanceRemesh::Auto;
  /// Auto remeshes inputs with more than this share of faces under the target angle: one that
  /// meets issue 32's goal (at most 1 %) is a tessellation someone chose, and only polished.
  static constexpr double kRemeshAbove = 0.01;
  /// The remeshing's sizing field asks for at most this many faces (it is coarsened uniformly when
  /// it would ask for more); 0: ten times the input's faces, at least 50,000.
  std::size_t max_faces = 0;
  /// The user's element size (core/size_field.h); any of it set makes auto remesh, so that the
  /// surface follows it.
  SizeParams size;
  /// Collapses may remove at most this fraction of the faces (two per removed vertex).
  double max_face_change = 0.02;
  /// The statistic's constants; defaults fitted by bench/tune_enhance (see enhance_defaults.h).
  double tail_k;
  double tail_weight;                   ///< gamma
  double fidelity_weight;               ///< lambda
  double flip_dihedral_deg;             ///< largest dihedral angle across a flipped edge
  /// kAutomaticTimeLimit (the default): automatic_enhance_time_limit; 0: none. At the limit (or
  /// the deadline) no further round starts, and the best so far is kept; a remeshing under way is
  /// taken back (the input's own faces are enhanced instead, if time is left).
  double time_limit_seconds = kAutomaticTimeLimit;
  /// The whole command's deadline (the pipeline gives the enhancement a share of the time left).
  Deadline deadline;
  std::function<void(double)> progress; ///< called with the fraction done (0 every few hundred steps of the remeshing: a stop it throws ends that too)
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
  std::size_t cap_flips = 0;            ///< caps' long edges flipped, crease or not (not in flips)
  std::size_t removed_vertices = 0;     ///< of valence 3 (two faces each)
  std::size_t split_edges = 0;          ///< on a plane, under needles (two faces each)
  double max_deviation = 0;             ///< the bound used, relative to the reference's diagonal
  std::size_t line_vertices = 0;        ///< on a crease or the boundary: slid along it
  std::size_t fixed_vertices = 0;       ///< corners and non-manifold vertices: kept
  std::size_t undone_moves = 0;         ///< vertex moves taken back by the guards
  std::size_t input_self_intersections = 0;  ///< intersecting face pairs of the input (the guards allow no more)
  bool remeshed = false;                ///< the remeshing ran (and was kept)
  std::size_t remesh_splits = 0, remesh_collapses = 0, remesh_flips = 0;
  /// Seconds the remeshing took, its runs again included (kept or taken back); `seconds` holds it
  /// too: the rest is the rounds and the settling fit.
  double remesh_seconds = 0;
  /// Times the remeshing crossed itself and was run again, finer where it crossed (kept or not).
  std::size_t remesh_crossing_refinements = 0;
  /// The sizing field, relative to the reference's diagonal: its shortest length, and its base
  /// (the input's own density, where nothing asks for less).
  double sizing_shortest = 0, sizing_base = 0;
  std::size_t sizing_faces = 0;         ///< the faces the sizing field asks for (estimated over the input)
  bool sizing_capped = false;           ///< coarsened to stay within max_faces
  /// The field the kept remeshing followed (null when none was kept): the tets may follow it too.
  std::shared_ptr<const SizeField> size_field;
  std::size_t faces_before = 0, faces_after = 0;
  QualityTail before, after;
  double seconds = 0;
  bool stopped_by_time_limit = false;   ///< the time limit or the deadline ended the remeshing or the rounds
  /// The remeshing when it made the surface cross itself or reached its face limit, rounds' edits
  /// that made it cross itself, vertex moves the guards put back, and every round when none gained.
  std::vector<TakenBack> taken_back;
};

/// \throws InvalidInput "enhance: ..." if a parameter is outside its range (NaN never is inside)
/// or the time limit is neither -1, 0 nor a positive number of seconds.
void check_enhance_params(const EnhanceParams& params);

/// Enhance `mesh` in place. `reference` is the surface to stay on (the original mesh); nullptr
/// means the input itself. \throws InvalidInput if params are out of range or the mesh is empty.
EnhanceResult enhance(TriMesh& mesh, const TriangleSoup* reference, const EnhanceParams& params = {});

/// {mean_q, stddev_q, q_p05, under_target_fraction, min_angle_deg}.
nlohmann::ordered_json to_json(const QualityTail& tail);

/// The run as `meshprep enhance --json` writes it, in this order: rounds, kept_round, flips,
/// cap_flips, removed_vertices, split_edges, line_vertices, fixed_vertices, undone_moves,
/// guards_taken_back (json_values.h), remesh, parameters (the
/// bound used, whether it was automatic, and the settings of `params`), tail_before, tail_after,
/// time_seconds, stopped ("time limit" or null). The pipeline's stage record picks from it.
nlohmann::ordered_json to_json(const EnhanceResult& result, const EnhanceParams& params);

}  // namespace meshprep
