#include "meshprep/preprocess/repair/repair.h"

#include "repair/drop_lone_faces.h"
#include "repair/envelope_deviation.h"
#include "repair/envelope_surface.h"
#include "repair/fill_holes.h"
#include "repair/orient_components.h"
#include "repair/remove_self_intersections.h"
#include "repair/split_nonmanifold.h"
#include "repair/split_t_junctions.h"
#include "repair/weld_vertices.h"
#include "shared/edge_lengths.h"

#include "meshprep/core/errors.h"
#include "meshprep/preprocess/repair/repair_parameters.h"
#include "meshprep/quality/face_edges.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/surface_distance.h"
#include "meshprep/quality/topology.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace meshprep {

namespace {

// A repair never returns an empty surface: what it removed is the problem to name.
[[noreturn]] void refuse_empty(std::size_t input_faces, const RepairResult& result) {
  std::array<char, 32> weld_distance_text;
  std::snprintf(weld_distance_text.data(), weld_distance_text.size(), "%.3g", result.weld_distance);
  throw InvalidInput("repair: no face is left of " + std::to_string(input_faces) + ": " +
                     std::to_string(result.degenerate_faces) + " name a vertex twice once vertices within " +
                     weld_distance_text.data() + " are welded (zero-area faces), " +
                     std::to_string(result.duplicate_faces) + " repeat another face's vertices, " +
                     std::to_string(result.removed_faces) + " pieces lie inside the solid; nothing is written");
}

// Step 7: `surface` rebuilt from `soup` (the surface as steps 1-5 left it) on the grid, and its
// distance from `soup` measured.
RepairEnvelope rebuild_on_envelope(TriangleSoup& surface, const TriangleSoup& soup, std::string reason,
                                   const RepairParams& params, const std::function<void()>& poll) {
  const auto start = std::chrono::steady_clock::now();
  RepairEnvelope envelope;
  envelope.reason = std::move(reason);
  envelope.cells = params.envelope_cells;
  envelope.bound = params.fidelity_bound;
  detail::EnvelopeSurface rebuilt = detail::envelope_surface(soup, params.envelope_cells, poll);
  if (rebuilt.surface.triangles.empty())
    throw InvalidInput("repair: the envelope route found no point of a " + std::to_string(params.envelope_cells) +
                      "-cell grid inside the surface (it encloses nothing thicker than a cell: give more "
                      "--envelope-cells); nothing is written");
  envelope.cell = rebuilt.cell;
  envelope.grid_points = rebuilt.grid_points;
  envelope.faces = rebuilt.surface.triangles.size();
  envelope.relabelled_specks = rebuilt.relabelled_specks;
  poll();
  const double diagonal = bbox_diagonal(soup);
  const detail::EnvelopeDeviation deviation =
      detail::envelope_deviation(rebuilt.surface, soup,
                                 envelope.bound > 0 ? envelope.bound * diagonal : std::numeric_limits<double>::infinity(),
                                 rebuilt.cell,
                                 RepairEnvelope::kListedPlaces);
  envelope.distance_max = deviation.max / diagonal;
  envelope.distance_rms = deviation.rms / diagonal;
  envelope.samples_over_bound = deviation.over_bound;
  for (const detail::DeviationPlace& place : deviation.places)
    envelope.places.push_back({place.point, place.distance / diagonal});
  surface = std::move(rebuilt.surface);
  envelope.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return envelope;
}

}  // namespace

double automatic_repair_time_limit(std::size_t faces) {
  return kAutomaticTimeLimitScale *
         (kRepairTimeLimitFloorSeconds + kRepairTimeLimitPerFaceSeconds * static_cast<double>(faces));
}

RepairResult repair(TriangleSoup& surface, const RepairParams& params) {
  if (!(params.weld_tolerance >= 0 && std::isfinite(params.weld_tolerance)))
    throw InvalidInput("repair: the weld tolerance must be a finite number >= 0");
  if (params.max_hole) check_parameter("repair", repair_parameters().max_hole, *params.max_hole);
  check_parameter("repair", repair_parameters().envelope_cells, static_cast<double>(params.envelope_cells));
  check_parameter("repair", repair_parameters().time_limit_seconds, params.time_limit_seconds);
  const auto start = std::chrono::steady_clock::now();
  // The exact cut's limit counts from the repair's start (used on the automatic route only).
  const double cut_limit = params.time_limit_seconds == kAutomaticTimeLimit
                               ? automatic_repair_time_limit(surface.triangles.size())
                               : params.time_limit_seconds;
  const Deadline cut_deadline = Deadline::in_seconds(cut_limit);
  const auto poll = [&params] {
    if (params.cancelled && params.cancelled()) throw Cancelled("repair stopped");
  };
  RepairResult result;
  result.weld_distance = params.weld_tolerance * detail::median_edge_length(surface);
  const std::size_t input_faces = surface.triangles.size();
  const detail::WeldCounts weld = detail::weld_vertices(surface, result.weld_distance, detail::WeldScope::open_edges);
  result.input_closed = weld.input_closed;
  result.welded_vertices = weld.welded_vertices;
  result.degenerate_faces = weld.degenerate_faces;
  result.duplicate_faces = weld.duplicate_faces;
  result.unused_vertices = weld.unused_vertices;
  if (surface.triangles.empty()) refuse_empty(input_faces, result);
  if (!weld.input_closed) result.t_junction_splits = detail::split_t_junctions(surface, result.weld_distance);
  // The steps below walk the same sorted face edges: sorted once, and again only after a step
  // that changed the faces.
  poll();
  std::vector<FaceEdge> uses = sorted_face_edges(surface);
  detail::SplitCounts split = detail::split_nonmanifold(surface, uses);
  result.split_edges = split.split_edges;
  result.split_vertices = split.split_vertices;
  if (split.split_vertices > 0) uses = sorted_face_edges(surface);
  result.dropped_lone_faces = detail::drop_lone_faces(surface, uses);
  if (result.dropped_lone_faces > 0) uses = sorted_face_edges(surface);
  poll();
  const detail::OrientCounts orient = detail::orient_components(surface, uses);
  result.components = orient.components;
  result.flipped_faces = orient.flipped_faces;
  result.inverted_components = orient.inverted_components;
  if (orient.flipped_faces > 0 || orient.inverted_components > 0) uses = sorted_face_edges(surface);
  poll();
  result.holes = detail::fill_holes(surface, uses, params.max_hole);
  for (const RepairHole& hole : result.holes) ++(hole.filled ? result.filled_holes : result.open_holes);
  // A bow-tie on a hole's rim is one fan again once the patch joins its fans (fill_holes.cpp):
  // its copies are welded back, and what is still not manifold is split again.
  if (result.split_vertices > 0 && result.filled_holes > 0) {
    detail::weld_vertices(surface, 0);
    split = detail::split_nonmanifold(surface, sorted_face_edges(surface));
    result.split_edges = split.split_edges;
    result.split_vertices = split.split_vertices;
  }
  poll();
  if (result.filled_holes > 0) uses = sorted_face_edges(surface);
  std::string envelope_reason;
  TriangleSoup before_cut;
  // The envelope needs a closed surface to tell inside from outside: with a hole left open (a
  // sheet's outline) the exact route's result stands, whatever it left.
  const bool fallback = params.route == RepairRoute::automatic && result.open_holes == 0;
  std::optional<detail::SelfIntersectionCounts> cut;
  if (params.route == RepairRoute::envelope) {
    envelope_reason = "asked (route envelope)";
    before_cut = surface;
  } else {
    if (fallback) before_cut = surface;
    struct PastTheLimit {};
    const auto poll_and_time = [&] {
      poll();
      if (fallback && cut_deadline.passed()) throw PastTheLimit{};
    };
    try {
      cut = detail::remove_self_intersections(surface, uses, params.keep_cavities, poll_and_time);
    } catch (const PastTheLimit&) {
      surface = before_cut;
      envelope_reason = "the exact cut was not done " + parameter_text(cut_limit) + " s after the repair began";
    }
  }
  if (cut) {
    const detail::SelfIntersectionCounts& crossing = *cut;
    result.intersecting_pairs = crossing.intersecting_pairs;
    result.cut_faces = crossing.cut_faces;
    result.removed_faces = crossing.removed_faces;
    result.nested_components = crossing.nested_components;
    result.cavities = crossing.cavities;
    result.separated_pinches = crossing.separated_pinches;
    result.free_of_self_intersections = crossing.found_none;
    if (surface.triangles.empty()) refuse_empty(input_faces, result);
    if (fallback && !crossing.found_none) {
      poll();
      const std::size_t left = find_self_intersections(surface).count;
      result.free_of_self_intersections = left == 0;
      if (left > 0)
        envelope_reason = "the exact cut left " + std::to_string(left) + " pairs of faces crossing";
    }
    // A closed surface cut must stay closed; where pieces faced both ways were dropped on
    // coplanar faces flush only to rounding (a rotated part's), it can come out cracked.
    if (fallback && envelope_reason.empty() && crossing.cut_faces > 0) {
      const Topology after = analyze_topology(surface);
      if (!after.closed || !after.manifold)
        envelope_reason = "the exact cut left " + std::to_string(after.border_edges + after.non_manifold_edges) +
                          " edges open or non-manifold";
    }
  }
  if (!envelope_reason.empty()) {
    poll();
    result.route = "envelope";
    result.envelope = rebuild_on_envelope(surface, before_cut, envelope_reason, params, poll);
    result.free_of_self_intersections = false;  // by construction, but the caller's check confirms it
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace meshprep
