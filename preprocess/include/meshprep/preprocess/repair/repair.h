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
/// 7. the envelope route (repair.route): where the exact cut leaves faces crossing (its new
///    points rounded to doubles can cross again where cut curves meet within rounding distance,
///    and its passes are bounded), or when asked, the surface is rebuilt from the soup as steps 1-5
///    left it: the boundary of where its generalised winding number is at least one half, on a grid
///    of envelope_cells across the longest side (envelope_surface.h, after fTetWild's inside test,
///    Hu et al. 2020). Always closed, manifold and free of crossings; its vertices lie on the input,
///    its faces within about half a cell of it, and the distance both ways is measured and reported,
///    with the places farther than the fidelity bound. On the automatic route it also takes over
///    when the exact cut runs past the repair's time limit.
/// The caller checks the result (fem's check_fem_readiness) and refuses what is left. A repair
/// that would leave no face throws InvalidInput, naming what it removed.

#include "meshprep/core/deadline.h"
#include "meshprep/core/mesh.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace meshprep {

/// How crossing faces are mended (step 6 or 7).
enum class RepairRoute { automatic, exact, envelope };

/// The automatic time limit: the exact cut measured about 6 us per face (two overlapping bunnies,
/// 150,000 faces, 0.9 s), so the per-face share leaves it more than ten times that, and the floor
/// the small parts' fixed costs.
inline constexpr double kRepairTimeLimitFloorSeconds = 10;
inline constexpr double kRepairTimeLimitPerFaceSeconds = 1e-4;
/// kRepairTimeLimitFloorSeconds + kRepairTimeLimitPerFaceSeconds * faces (times kAutomaticTimeLimitScale).
double automatic_repair_time_limit(std::size_t faces);

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
  RepairRoute route = RepairRoute::automatic;
  /// The envelope route's grid: cells across the longest side of the bounding box.
  std::size_t envelope_cells = 128;
  /// The envelope route lists the places where its surface lies farther from the input than this
  /// fraction of the diagonal (no parameter of its own: repair_solid.h passes the enhancement's,
  /// the pipeline its enhance.max_deviation).
  double fidelity_bound = 0;
  /// On the automatic route, seconds from the repair's start by which the exact cut must be done,
  /// or the envelope route rebuilds the solid instead (the exact route's cut has no limit but the
  /// command's); kAutomaticTimeLimit: automatic_repair_time_limit of the input's faces; 0: none.
  double time_limit_seconds = kAutomaticTimeLimit;
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

/// A place where the envelope route's surface lies farther from the input than the fidelity bound.
struct RepairPlace {
  Vec3 point = Vec3::Zero();
  double distance = 0;  ///< as a fraction of the input's bounding-box diagonal
};

/// What the envelope route did (step 7). Distances are fractions of the input's bounding-box
/// diagonal, measured both ways (envelope_deviation.h: the input's inner walls are not measured).
struct RepairEnvelope {
  std::string reason;           ///< why it ran: asked, or the exact cut's leftovers
  std::size_t cells = 0;        ///< across the longest side
  double cell = 0;              ///< the grid's spacing, in the surface's units
  std::size_t grid_points = 0;
  std::size_t relabelled_specks = 0;  ///< grid points of groups smaller than a cube, given the other label
  std::size_t faces = 0;              ///< the grid's surface
  std::size_t reduced_faces = 0;      ///< after repair_solid.h's simplification (0: not simplified)
  double distance_max = 0, distance_rms = 0;
  double bound = 0;                    ///< the fidelity bound the places are judged by
  std::size_t samples_over_bound = 0;  ///< of the measured samples
  std::vector<RepairPlace> places;     ///< the farthest places over the bound (at most kListedPlaces)
  static constexpr std::size_t kListedPlaces = 20;
  double seconds = 0;
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
  /// "exact" (step 6) or "envelope" (step 7; then the counts of step 6 are those of the attempt
  /// the envelope replaced, if any).
  std::string route = "exact";
  std::optional<RepairEnvelope> envelope;
  double seconds = 0;
};

/// Repair `surface` in place (steps above).
RepairResult repair(TriangleSoup& surface, const RepairParams& params = {});

/// What the envelope route did, as a clause the summaries append ("; the exact cut left 3 pairs of
/// faces crossing: the solid rebuilt on a 128-cell grid (envelope route), 1.1e-03 of the diagonal
/// from the input at most, 2.0e-04 RMS, 4 places over the 0.002 bound"); empty for the exact route.
std::string envelope_summary(const RepairResult& result);

/// The run as `meshprep repair --json` writes it: the fields above by name (holes as an array of
/// objects), time_seconds last.
nlohmann::ordered_json to_json(const RepairResult& result);

}  // namespace meshprep
