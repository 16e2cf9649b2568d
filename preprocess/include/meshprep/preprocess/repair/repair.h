#pragma once
/// \file repair.h
/// The repair stage (issue 33): a dirty surface mended without moving the input's vertices. In order:
/// 1. weld: exact copies of a vertex become one, and vertices on open edges (an edge that one face
///    alone uses) closer than weld_tolerance x the median edge length too (the lowest index of each
///    cluster, where it is: welding never moves a vertex). A closed input is welded at its exact
///    copies only: a thin wall is never welded shut, a valid part comes out as it went in;
///    Then T-junctions: a vertex of an open edge lying on another open edge (within the same
///    distance) splits that edge's face there, so that both sides of the seam share it;
/// 2. faces that name a vertex twice after welding, and faces repeating another's three vertices,
///    are removed (every copy when they face both ways and their edges have two other faces each: the
///    wall two solids share; a part written double-sided keeps one copy of each face); vertices no
///    face uses are dropped;
/// 3. non-manifold edges and vertices are split: each sheet meeting there gets its own copy of the
///    vertices; the faces on an edge with more than two are paired by their angles around it, so
///    two boxes touching along an edge stay two closed boxes (a bow-tie on a hole's rim is joined
///    again by the hole's patch, step 5);
///    Then faces no other face shares an edge with (a fin the split took off a solid's edge, a
///    stray triangle) are removed, unless they are all there is: they enclose nothing;
/// 4. orientation: each edge-connected component is made consistent from its first face, across
///    its manifold edges, and a closed component enclosing negative volume is turned outward;
/// 5. holes: each boundary loop is filled after Liepa 2003 (a minimum-dihedral, then minimum-area
///    triangulation, refined to the density of the surface around it and faired with a
///    bi-Laplacian) but an open sheet's outline, or with max_hole given, each loop no longer than
///    max_hole x the bounding box's diagonal; the others stay open.
/// 6. self-intersections: every face is cut exactly along the curves where others cross or touch
///    it, and the pieces bounding the union of what the surface encloses are kept (those just
///    outside which the winding number is 0). Overlapping parts become one solid, a wall two parts
///    share goes, a fold loses its inner sheets; a closed part inside another that touches nothing
///    is dropped, or kept as a cavity's wall with keep_cavities. It comes after the holes because
///    the winding number only tells inside from outside for a closed surface.
///    Why this method: every kept piece lies on the input (to the rounding of the new points), so
///    the surface moves by nothing measurable, and it gives the union the issue asks of touching,
///    overlapping and nested parts, which a local remesh of the crossing faces cannot.
/// The caller checks the result (fem's check_fem_readiness) and refuses what is left. A repair
/// that would leave no face throws InvalidInput, naming what it removed.

#include "meshprep/core/mesh.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace meshprep {

struct RepairParams {
  /// Vertices closer than this fraction of the median edge length are welded. A file that splits
  /// its vertices writes each copy with the same digits, so exact copies dominate; the margin
  /// takes exporters that round differently per copy, and stays far below any real edge.
  double weld_tolerance = 1e-3;
  /// Given, boundary loops longer than this fraction of the bounding box's diagonal are left open;
  /// unset ("auto"), every loop is filled but an open sheet's outline (a terrain's, a mask's: no
  /// solid's hole). repair_parameters.cpp says why length cannot tell them apart.
  std::optional<double> max_hole;
  /// A closed part inside another that touches nothing is kept as the wall of a void (facing
  /// inwards) instead of being dropped.
  bool keep_cavities = false;
  /// Optional, asked between the steps and between the self-intersection step's passes; true:
  /// throw Cancelled (the surface is then partly repaired: repair a copy to keep the input).
  std::function<bool()> cancelled;
};

/// One boundary loop, filled or left open. Lengths and areas are in the surface's units.
struct RepairHole {
  std::size_t rim_vertices = 0;
  double rim_length = 0;
  bool filled = false;
  std::string left_open;            ///< why it was not filled; empty if it was
  std::size_t patch_faces = 0;      ///< faces the patch added
  std::size_t patch_vertices = 0;   ///< vertices the patch added (its refinement's)
  double patch_area = 0;
  double plane_distance = 0;  ///< largest distance of the patch's vertices to the rim's least-squares plane
  bool faired = false;        ///< false if the fairing's solve failed (the patch stays refined, not faired)
};

struct RepairResult {
  double weld_distance = 0;             ///< the welding distance used, in the surface's units
  /// The input, its exact copies joined, had no open edge: no other vertex was welded, and no
  /// later step may leave it open (a solid is never turned into a sheet).
  bool input_closed = false;
  std::size_t welded_vertices = 0;      ///< vertices merged into another
  std::size_t degenerate_faces = 0;     ///< removed: a vertex twice after welding
  /// Removed: another face's three vertices (every copy when they are a wall two solids share).
  std::size_t duplicate_faces = 0;
  std::size_t unused_vertices = 0;      ///< dropped: no face uses them
  std::size_t t_junction_splits = 0;    ///< faces split at a vertex of the seam's other side
  /// Non-manifold edges (more than two faces) and vertices (bow-ties, split edges' ends) given a
  /// copy per sheet and still split at the end: a bow-tie on a hole's rim whose fans the hole's
  /// patch joins is one vertex again.
  std::size_t split_edges = 0, split_vertices = 0;
  std::size_t dropped_lone_faces = 0;   ///< faces sharing no edge with another (fins, strays), removed
  std::size_t flipped_faces = 0;        ///< turned to agree with their component's first face
  std::size_t inverted_components = 0;  ///< closed components turned outward (every face flipped)
  std::size_t components = 0;           ///< edge-connected components
  std::vector<RepairHole> holes;        ///< every boundary loop after orientation
  std::size_t filled_holes = 0, open_holes = 0;
  std::size_t intersecting_pairs = 0;  ///< pairs of faces crossing, overlapping or touching
  std::size_t cut_faces = 0;           ///< faces triangulated again along where others meet them
  std::size_t removed_faces = 0;       ///< pieces inside the union, or doubled, dropped
  std::size_t nested_components = 0;   ///< closed parts inside another touching nothing, dropped
  std::size_t cavities = 0;            ///< such parts kept as cavities (keep_cavities)
  std::size_t separated_pinches = 0;   ///< copies of a point where parts touch, moved apart
  /// The step's last search for intersecting pairs was on the surface as returned and found none
  /// (check_fem_readiness can then skip its own).
  bool free_of_self_intersections = false;
  double seconds = 0;
};

/// Repair `surface` in place (steps above).
RepairResult repair(TriangleSoup& surface, const RepairParams& params = {});

/// The run as `meshprep repair --json` writes it: the fields above by name (holes as an array of
/// objects), time_seconds last.
nlohmann::ordered_json to_json(const RepairResult& result);

}  // namespace meshprep
