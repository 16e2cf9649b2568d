#pragma once
/// \file knife_edges.h
/// Knife edges opened before the tets are made. At a boundary edge where the solid is a thin wedge
/// (its interior angle alpha small, and neither the one tet the two faces force nor two tets joined
/// at one inner point good), no tets of that boundary reach the improvement's goal
/// (fem/src/improve/surface_limits.h gives the bound). Often the wedge is a flaw of the input a
/// local change of the surface removes: a sliver left by a cut (two faces folded onto each other
/// at a tiny edge), a needle face folded over its neighbour. Each such edge is given the best of a
/// few local edits, its flip or the collapse of an edge of its two faces (to either end or to the
/// middle), kept only if
/// - it raises the bounds of the edges it changes (their sorted list, the worst first), and makes
///   no face of them worse-shaped than the worst it replaces (or than the goal);
/// - the new faces lie within max_deviation of the reference surface, and the faces they replace
///   within max_deviation of the new ones (both sampled), which is the edit's displacement;
/// - it makes no new crossing with the faces around (the exact test of self_intersections.h), and
///   keeps the surface a manifold (OpenMesh's link condition) and its patches (no flip across a
///   patch border).
/// A cap face (an angle near 180 degrees) caps the tets on it the same way (face_bound_deg): it is
/// given the edits of its three edges. What no edit opens within the bound stays, listed with its
/// bound: the report names it.

#include "meshprep/core/mesh.h"
#include "meshprep/core/soup_view.h"

#include <nlohmann/json.hpp>

#include <vector>

namespace meshprep {

struct KnifeEdgeParams {
  /// The tets' goal (ImproveParams::goal_min_dihedral_deg): an edge whose bound is below it is a
  /// knife edge.
  double goal_min_dihedral_deg = 15;
  /// ImproveParams::goal_max_dihedral_deg: with the goal above, it weighs the obtuse angles of
  /// the tets on a cap face (tet_objective.h).
  double goal_max_dihedral_deg = 160;
  /// How far the surface may move, in the units of the mesh: the caller's fidelity bound (the
  /// pipeline's enhance.max_deviation times the input's diagonal).
  double max_deviation = 0;
};

/// One place where the surface was changed, or one left.
struct KnifeEdgePlace {
  const char* kind = "edge";  ///< "edge": a knife edge; "cap": a face with an angle near 180 degrees
  Vec3 place = Vec3::Zero();  ///< the edge's midpoint, the face's centroid
  /// The solid's angle at a knife edge; a cap's largest angle.
  double interior_angle_before_deg = 0;
  double bound_before_deg = 0;
  /// After the edit: the lowest bound of the edges it made (the goal if all reach it), and the
  /// smallest interior angle among them. Equal to the "before" figures for an edge left.
  double interior_angle_after_deg = 0;
  double bound_after_deg = 0;
  double displacement = 0;  ///< in the units of the mesh; 0 for an edge left
  const char* edit = "";    ///< "flip", "collapse"; "" for an edge left
};

struct KnifeEdgeResult {
  std::size_t knife_edges_before = 0, knife_edges_after = 0;
  /// The lowest bound over the surface's edges, before and after (the goal when none is below it).
  double surface_bound_before_deg = 0, surface_bound_after_deg = 0;
  std::vector<KnifeEdgePlace> edits;  ///< in the order made
  std::vector<KnifeEdgePlace> left;   ///< the knife edges left, lowest bound first
  double max_displacement = 0;        ///< the largest of the edits' displacements
  double seconds = 0;
};

/// Opens the knife edges of the closed, manifold surface `mesh` (oriented either way) within
/// params.max_deviation of `reference` (the surface the caller measures fidelity against), and
/// garbage-collects the mesh when an edit was made. The patches travel with the faces.
KnifeEdgeResult open_knife_edges(TriMesh& mesh, const SoupView& reference, const KnifeEdgeParams& params);

/// The result as JSON: counts, bounds and every place (point, angles, bounds, displacement, edit).
nlohmann::ordered_json to_json(const KnifeEdgeResult& result);

}  // namespace meshprep
