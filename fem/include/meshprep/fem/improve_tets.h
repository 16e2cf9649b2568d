#pragma once
/// \file improve_tets.h
/// Tet mesh improvement: what TetGen leaves (slivers across the part, caps, needles) made into
/// tets a solver can use, with the boundary triangles kept exactly. The schedule follows Klingner
/// & Shewchuk, "Aggressive tetrahedral mesh improvement" (IMR 2007): the tets below the goal are
/// taken worst first, and each is given, in order,
/// - the best topological move around it: edge removal (3-2, 4-4 and larger flips, Shewchuk 2002)
///   on its six edges and multi-face removal (2-3 and larger flips) on its four faces;
/// - smoothing of its free corners (Freitag's active-set method, maximising the worst tet);
/// - contraction of a free corner into a neighbour (the vertex no position suits);
/// - the best few topological moves again, each followed by smoothing of the corners it touched
///   and judged together (a flip that only pays once a vertex has moved);
/// - a new vertex inside it, joined to the best cavity around it.
/// A move is kept only if it raises the worst quality among the tets it replaces, and only if
/// every tet it makes is positive by an exact orientation test: no tet is ever inverted, and the
/// sorted list of qualities rises at every move, so nothing cycles. A pass ends when no tet
/// below the goal is left to try (or after a budget of tries bounded by the tets below the goal at
/// the start); the run stops when the goal is reached, when a pass gains nothing (the number below
/// the goal did not fall and the worst tet rose by less than a smoothing step's least gain), or at
/// a pass or time limit.
///
/// The objective is the biased minimum sine of the dihedral angles (fem/src/improve/
/// tet_objective.h): the sine is zero exactly at 0 and 180 degrees, and the obtuse angles are
/// weighted so that goal_max_dihedral_deg scores like goal_min_dihedral_deg.
///
/// Kept exactly: every constrained face (the boundary: faces with one tet; faces between two
/// regions; any face listed in boundary_faces) with its corners, which never move unless
/// boundary_deviation allows the outer boundary's corners to slide on the surface (then each
/// boundary face keeps its corners, its tag and its side, within that distance); the regions
/// (no move mixes two); the boundary tags. What the surface forbids (fem/src/improve/
/// surface_limits.h): at a boundary edge whose interior angle alpha is below the goal, every tet
/// there has a dihedral angle <= alpha; below twice the goal, either one tet spans the edge, the
/// one the two boundary faces force, or one of several has a dihedral angle <= alpha / 2. Edges
/// where the better of the two is below the goal are listed with that bound.

#include "meshprep/core/deadline.h"
#include "meshprep/core/taken_back.h"
#include "meshprep/fem/tet_mesh.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace meshprep {

/// The automatic time limit, floor + per tet. On TetGen's own tets of the 19 CAD parts of the
/// shared data, the runs that reach the goal take 0.2-22 µs per tet and at most 2.5 s; those that
/// cannot reach it gain little after their first seconds (bench/RESULTS.md, "Time budgets"). So
/// about twice the slowest goal-reaching run per tet (the VM's speed drifts up to 2x), and a floor
/// of four times the longest, for the small meshes whose runs cannot reach the goal.
inline constexpr double kAutomaticTimeLimitFloorSeconds = 10;
inline constexpr double kAutomaticTimeLimitPerTetSeconds = 50e-6;
/// kAutomaticTimeLimitFloorSeconds + kAutomaticTimeLimitPerTetSeconds * tets (times kAutomaticTimeLimitScale).
double automatic_improve_time_limit(std::size_t tets);

struct ImproveParams {
  /// A tet is below the goal if a dihedral angle is smaller than goal_min_dihedral_deg or larger
  /// than goal_max_dihedral_deg; those are the tets the improvement works on. Degrees,
  /// 0 < min < 60 < max < 180.
  double goal_min_dihedral_deg = 15;
  double goal_max_dihedral_deg = 160;
  bool topological_moves = true;  ///< edge and multi-face removal
  bool smoothing = true;          ///< moving free vertices
  bool insertion = true;          ///< new interior vertices
  std::size_t max_passes = 10;    ///< >= 1
  /// How far the boundary may move, as a fraction of the mesh's bounding-box diagonal: boundary
  /// vertices slide on the surface (within their first faces, along creases, corners fixed) where
  /// that raises the worst tet, the faces staying within this distance of the boundary as it was
  /// (fem/src/improve/boundary_slides.h). 0 or unset (the default): the boundary is kept exactly.
  /// With a goal past the default, each of the two stages may use half. In [0, 1].
  std::optional<double> boundary_deviation;
  /// kAutomaticTimeLimit (the default): automatic_improve_time_limit; 0: none; the run stops after
  /// the move under way, with the best tets so far.
  double time_limit_seconds = kAutomaticTimeLimit;
  /// The whole command's deadline: the time limit is shortened to the time left.
  Deadline deadline;
  std::function<void(double fraction)> progress;  ///< optional, the share of the goal reached
  /// Optional, asked every few hundred moves, and per block of tets while the run sets up (from
  /// any of the threads doing it: it must be thread-safe); true: throw Cancelled.
  std::function<bool()> cancelled;
};

/// The goals' presets (`--tet-quality`): "default", ImproveParams' own 15/160 deg (the floor the
/// verdict's 10/165 leaves room under); "high", 20/150 deg (a quality mode: Stellar, Klingner &
/// Shewchuk 2007, reaches 23-31 deg on its test set). A goal past the default is climbed from the
/// default's result and kept only if no worse (improve_tets).
struct TetQualityPreset {
  const char* name;
  double goal_min_dihedral_deg, goal_max_dihedral_deg;
};
const std::vector<TetQualityPreset>& tet_quality_presets();
/// The name of the preset whose goals `params` has, or "custom".
std::string tet_quality_of(const ImproveParams& params);
/// Sets the goals of preset `name` ("custom" leaves them). \throws InvalidInput for another name.
void apply_tet_quality(ImproveParams& params, const std::string& name);

/// A boundary edge where the surface caps the smallest dihedral angle below the goal.
struct LimitingBoundaryEdge {
  std::uint32_t a = 0, b = 0;  ///< point indices
  Vec3 midpoint = Vec3::Zero();
  double interior_angle_deg = 0;  ///< the solid's angle at the edge
  double bound_deg = 0;           ///< no tets with this boundary have a smallest dihedral angle above it
};

struct ImproveResult {
  double min_dihedral_before_deg = 0, max_dihedral_before_deg = 0;
  double min_dihedral_after_deg = 0, max_dihedral_after_deg = 0;
  std::size_t below_goal_before = 0, below_goal_after = 0;  ///< tets
  std::size_t tets_before = 0, tets_after = 0;
  std::size_t edge_removals = 0;        ///< including 3-2 and 4-4 flips
  std::size_t multi_face_removals = 0;  ///< including 2-3 flips
  std::size_t vertex_moves = 0;         ///< successful smoothing steps
  std::size_t compound_moves = 0;       ///< removals kept only with the smoothing after them
  std::size_t contractions = 0;         ///< free vertices merged into a neighbour
  std::size_t inserted_vertices = 0;
  std::size_t boundary_vertex_moves = 0;  ///< slides of boundary vertices on the surface
  /// The farthest a boundary vertex ended from where it began, as a fraction of the diagonal.
  double boundary_max_displacement_relative = 0;
  /// Tets flat to rounding with two faces on the boundary, removed first (a 2-2 flip of the
  /// boundary in its plane: fem/src/improve/flat_boundary_tets.h).
  std::size_t flat_boundary_tets_removed = 0;
  std::size_t passes = 0;
  std::string stopped_by;  ///< "goal reached", "no gain", "pass limit", "time limit", "nothing to do"
  double seconds = 0;
  /// Lowest bound first, at most 100 listed; limiting_edge_count counts them all.
  std::vector<LimitingBoundaryEdge> limiting_edges;
  std::size_t limiting_edge_count = 0;
  /// The lowest bound of limiting_edges (the goal when there are none): the best smallest
  /// dihedral angle the boundary allows, as far as these edges tell.
  double surface_bound_deg = 0;
  /// A detour towards a higher goal that ended no better, taken back (worst_quality: the smallest
  /// of the tets' biased smallest dihedral sines, improve_tets.cpp).
  std::vector<TakenBack> taken_back;
};

/// \throws InvalidInput "improve: <field> must be ..." if a goal is outside its range (NaN never is
/// inside), max_passes is 0 or the time limit is negative or not finite.
void check_improve_params(const ImproveParams& params);

/// Improves `mesh` in place (its points keep their indices; new points are appended; tets are
/// renumbered). \pre every tet positively oriented (TetGen's and the readers' are).
/// \throws InvalidInput for a second-order mesh (TetMesh::tet_edge_nodes: the moves are those of
///         linear tets; make the mesh second-order after improving it), a malformed mesh (indices, region count, a face shared by three tets,
///         tets that overlap) or parameters out of range; Cancelled when params.cancelled said so
///         (the mesh is then unchanged).
ImproveResult improve_tets(TetMesh& mesh, const ImproveParams& params = {});

/// "the surface itself allows at most 8.01 deg: 1 boundary edge too sharp, the first at (x, y, z)
/// with an interior angle of 16 deg" when the surface caps the smallest dihedral angle below
/// `threshold_deg`; empty otherwise.
std::string surface_limit_note(const ImproveResult& result, double threshold_deg);

/// The figures, for reports: keys as the struct's members.
nlohmann::ordered_json to_json(const ImproveResult& result);

}  // namespace meshprep
