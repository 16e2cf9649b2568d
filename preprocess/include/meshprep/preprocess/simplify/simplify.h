#pragma once
/// \file simplify.h
/// Reducing a triangle mesh to a target size by iterative edge collapse (Section 4 of the paper).
///
/// The costs (docs/simplification.md has the measurements behind every choice):
/// - CollapseCost::Bending (default): the paper's bending energy J of the volume spline over the
///   union of the edge's two 1-rings, with the sliding-landmark optimal point, used as a shape
///   factor on an error memory: cost = Q(p) (1 + mu J / |e|) + eps J |e|, Q the area-weighted
///   Garland-Heckbert quadric accumulated over the collapses, p the point minimising Q. J alone
///   orders edges by length, not by curvature (measured: 10x the Hausdorff distance), so it
///   cannot be the whole cost.
/// - CollapseCost::Distance: the paper's simple cost, the shortest distance between the central
///   point and its neighbours (the edge length), placed at the sliding-landmark point on the edge
///   and projected onto the local RBF height map (eq. 3) in the PCA tangent frame.
/// - CollapseCost::Quadric: OpenMesh's own Decimater + ModQuadric + ModNormalFlipping, the
///   baseline every other cost is measured against (no shape guard, no polish).
///
/// Safety, always on (Bending and Distance): OpenMesh's link condition (is_collapse_ok) keeps the
/// topology (closed stays closed, manifold stays manifold, genus unchanged); no face normal may
/// turn by more than 90 degrees or become degenerate; an open height field over a coordinate axis
/// (a terrain, quality/height_field.h) gets no face steeper than its steepest one, so it stays a
/// height field that fem's extrude_to_block can close; boundary vertices stay on the boundary and
/// non-manifold vertices are never moved; a collapse whose new faces have a smallest angle below
/// min(min_angle_deg, the old smallest angle around the edge) is refused. Self-intersections are
/// checked on the output: where the output intersects itself and the input did not, the
/// simplification restarts with half the error allowed where the crossing faces came from (up to
/// 6 times, one more ring each time), so the target may then not be reached.

#include "meshprep/core/mesh.h"
#include "meshprep/core/taken_back.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <functional>

namespace meshprep {

enum class CollapseCost {
  Bending,   ///< quadric error x bending-energy shape factor, free quadric placement
  Distance,  ///< shortest edge first, sliding-landmark point projected onto the local height map
  Quadric,   ///< OpenMesh Decimater + ModQuadric + ModNormalFlipping (baseline)
};

struct SimplifyParams {
  double keep_ratio = 0.1;        ///< fraction of the faces kept, (0, 1]; ignored if target_faces > 0
  std::size_t target_faces = 0;   ///< absolute target; 0 = use keep_ratio
  CollapseCost cost = CollapseCost::Bending;
  /// Smallest angle (degrees) a collapse may create, unless the faces around the edge already
  /// had a smaller one (then that is the bound). 0 disables the guard.
  double min_angle_deg = 20;
  /// Largest quadric estimate of the local deviation a collapse may reach, relative to the
  /// bounding-box diagonal (the RMS distance of the new vertex to the planes of the original
  /// faces it replaces). 0 = no limit; the target may then not be reached.
  double max_error = 0;
  /// After collapsing: edge flips and tangential relaxation that improve the smallest angles
  /// while staying within a quadric tolerance of the surface, each sweep followed by a
  /// least-squares fit of the vertices to the original surface along their normals (Bending and
  /// Distance only).
  bool polish = true;
  /// From this many edges on, the queue trades the exact cost order for memory locality: it takes
  /// the edges in bands of costs within 20 % of one another, each band place by place (in the
  /// Morton order of the surface), the cheapest first within each place. On big meshes the exact
  /// order jumps across the surface at every collapse and the collapses wait on memory; measured
  /// (docs/simplification.md): 0.71-0.86x the time on 0.8-1.2 M-face meshes, fidelity within the
  /// swing any change of order gives. Smaller meshes keep the exact order. 0 = always banded.
  std::size_t banded_queue_from_edges = 500000;
  /// Called with the fraction of the work done, in [0, 1].
  std::function<void(double)> progress;
};

struct SimplifyResult {
  std::size_t faces_before = 0, faces_after = 0, target_faces = 0;
  bool reached_target = false;  ///< faces_after within 1 % of the target
  double seconds = 0;           ///< the decimation itself (and the polish)
  std::size_t collapses = 0;
  std::size_t rejected_topology = 0;  ///< link condition or locked vertex
  std::size_t rejected_shape = 0;     ///< normal flip, degenerate face or smallest angle
  std::size_t rejected_error = 0;     ///< over max_error
  std::size_t energy_evaluations = 0; ///< bending energies computed
  std::size_t polish_flips = 0, polish_moves = 0;  ///< shape polish: edge flips, relaxation moves
  std::size_t fit_moves = 0;                        ///< least-squares fit to the original: vertex moves
  std::size_t intersection_retries = 0;  ///< restarts with a tighter error cap where the output crossed itself
  std::size_t reshapes = 0;  ///< relaxation sweeps between collapses (each time the face count halved)
  std::size_t stuck_restarts = 0;  ///< queue restarts after flips and relaxation freed collapses the shape guard refused
  bool banded_queue = false;  ///< the collapses ran in the banded order (banded_queue_from_edges)
  std::vector<TakenBack> taken_back;  ///< decimations started again because the output crossed itself
};

/// Simplify `mesh` in place (garbage-collected on return).
/// \throws InvalidInput if the mesh has no faces or the ratio is outside (0, 1].
SimplifyResult simplify(TriMesh& mesh, const SimplifyParams& params = {});

/// The number of faces simplify(mesh, params) aims at: params.target_faces, or keep_ratio of the
/// mesh's faces (for compositions that run the reduction in steps: simplify_and_enhance.h).
/// \throws InvalidInput as simplify does.
std::size_t simplify_target(const TriMesh& mesh, const SimplifyParams& params);

/// Whether `faces` is within 1 % of `target` (at least one face): SimplifyResult::reached_target.
bool reaches_target(std::size_t faces, std::size_t target);

/// The result as `meshprep simplify --json` writes it, in this order: faces_before, faces_after,
/// target_faces, reached_target, time_seconds, collapses, rejected {topology, shape, max_error},
/// energy_evaluations, intersection_retries, guards_taken_back (json_values.h), reshapes,
/// stuck_restarts, queue_order ("cost" or "cost_bands"), polish {flips, moves, fit_moves}. The pipeline's stage record picks from it.
nlohmann::ordered_json to_json(const SimplifyResult& result);

}  // namespace meshprep
