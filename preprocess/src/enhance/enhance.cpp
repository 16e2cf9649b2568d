#include "meshprep/preprocess/enhance/enhance.h"
#include "meshprep/preprocess/enhance/enhance_parameters.h"

#include "enhance/adaptive_remeshing.h"
#include "enhance/enhance_defaults.h"
#include "enhance/move_guards.h"
#include "enhance/quality_tail.h"
#include "enhance/sizing_field.h"
#include "enhance/surface_constraints.h"
#include "shared/surface_fit.h"
#include "enhance/surface_relocation.h"
#include "enhance/reference_cover.h"
#include "shared/edge_lengths.h"
#include "enhance/topology_cleanup.h"

#include "meshprep/core/soup_view.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/size_parameters.h"
#include "meshprep/core/finite_points.h"
#include "meshprep/core/origin_shift.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/surface_distance.h"
#include "meshprep/quality/triangle_bvh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

namespace meshprep {

EnhanceParams::EnhanceParams()
    : tail_k(detail::enhance_defaults::kTailK),
      tail_weight(detail::enhance_defaults::kTailWeight),
      fidelity_weight(detail::enhance_defaults::kFidelityWeight),
      flip_dihedral_deg(detail::enhance_defaults::kFlipDihedralDeg) {}

namespace {

using Points = std::vector<TriMesh::Point>;

Points points_of(const TriMesh& mesh) { return Points(mesh.points(), mesh.points() + mesh.n_vertices()); }

// One sweep of the least-squares fit to the reference along the normals (surface_fit.h): the
// charts and the projection put vertices on the surface, the fit puts the faces on it. Only
// vertices on no feature are fitted (the others stay on their lines), and only those that moved
// since `since` when it is given.
void fit_surface_vertices(TriMesh& mesh, const detail::SurfaceConstraints& constraints, double min_angle_cosine,
                          const Points* since = nullptr) {
  std::vector<char> movable(mesh.n_vertices(), 0);
  for (const auto v : mesh.vertices()) {
    const std::size_t i = static_cast<std::size_t>(v.idx());
    movable[i] = constraints.role(v) == detail::VertexRole::Surface && (!since || mesh.point(v) != (*since)[i]);
  }
  detail::fit_to_reference(mesh, constraints.reference_bvh(), min_angle_cosine, detail::HeightField{}, &movable);
}

// The rounds stop after this many in a row that did not improve the distribution (the best is
// kept). One stopped fandisk at 3.03 % of its faces under 20 degrees where the next rounds reach
// 2.0 %: splits need the next round's flips. It costs rounds (the bunny 6 instead of 4).
constexpr int kStaleRounds = 2;

// The automatic bound is never looser than the one the constants were tuned with: a coarse input
// (the corpus's sphere simplified by half is 2.9 % of its diagonal off) would otherwise let every
// face move that far.
constexpr double kLoosest = EnhanceParams::kLargestAutoDeviation;

// Relative distances under this count as none: the input lies on its reference.
constexpr double kOnReference = 1e-9;

// How far the input already is from the reference, relative to the reference's diagonal: their
// Hausdorff distance as the quality report measures it (dense sampling, refined where it is
// largest), with a tenth of its samples, rounded up to two significant digits. The rounding keeps
// the bound, and so the rounds, the same for inputs that differ by round-off (a mesh and its copy
// translated to 1e9, whose coordinates are rounded to 1.2e-7).
double input_deviation(const TriangleSoup& input, const TriangleSoup* reference, double diagonal) {
  // The same surface is on its reference exactly: sampled, a CAD export's needles (animation's
  // smallest angle is 6e-4 degrees) put the closest points 2.7e-7 of the diagonal off, which made
  // the pipeline's enhance (the input as its own reference) keep to that bound and not remesh.
  if (!reference || (reference->points == input.points && reference->triangles == input.triangles)) return 0;
  DistanceParams sampling;
  sampling.samples = DistanceParams().samples / 10;
  const double relative = surface_distance(input, *reference, sampling).hausdorff() / diagonal;
  if (!(relative > 0)) return 0;
  const double unit = std::pow(10.0, std::floor(std::log10(relative)) - 1);
  return std::ceil(relative / unit) * unit;
}

// The remeshing (adaptive_remeshing.h) and the rounds after it keep to half the deviation bound,
// and the remeshing's chords to a quarter (the sagitta of the curvature's sizing).
constexpr double kRemeshShareOfBound = 0.35;
constexpr double kChordShareOfBound = 0.25;
// The default limit on the remeshing's faces: this many per input face, or the floor (a small
// thin part needs many more faces than its export has: example021, 1,280 faces, asks for 25,000).
constexpr std::size_t kMaxFacesPerInputFace = 10;
constexpr std::size_t kMaxFacesFloor = 50000;
// When the splits reach the limit, the field is coarsened by this factor (a quarter of the faces)
// and the remeshing tried again, this many times in all.
constexpr double kCoarsening = 2;
constexpr std::size_t kSplitHeadroom = 4;
constexpr int kRemeshAttempts = 3;
// After remeshing, probes along the reference's bent edges are this fraction of a median edge apart.
constexpr double kProbesPerEdge = 0.25;
// A remeshing that made the surface cross itself is run again from the input, each crossing face
// asking for this share of its mean edge, at most this many times, before it is taken back (once
// was enough wherever it was: bones, camel, cheese, cow and hand; twice changed none of them).
constexpr double kCrossingRefinement = 0.5;
constexpr int kCrossingRefinements = 1;

// Where a remeshing crossed itself, two sheets of the surface pass closer than its faces there
// were long (hand's fingers, a cut curve's two sides): each crossing face asks for a finer length
// at its centroid, which the field grades around, so the rest of the surface keeps its remeshing.
void ask_finer_where_crossing(const SoupView& remeshed, const SelfIntersections& crossings,
                              std::vector<SizeDemand>& demands) {
  const auto ask = [&](std::size_t face) {
    const Triangle& t = remeshed.triangles[face];
    SizeDemand finer = face_density_demand(remeshed.points[t[0]], remeshed.points[t[1]], remeshed.points[t[2]]);
    finer.length *= kCrossingRefinement;
    demands.push_back(finer);
  };
  for (const auto& [f, g] : crossings.pairs) {
    ask(f);
    ask(g);
  }
}

// Remeshes the input to its sizing field; taken back if it made the surface cross itself.
// Returns whether it was kept.
bool remesh(TriMesh& mesh, detail::SurfaceConstraints& constraints, const EnhanceParams& params, double max_deviation,
            double diagonal, const Vec3& shift, std::size_t allowed_intersections, const std::function<bool()>& out_of_time,
            EnhanceResult& result) {
  detail::SizingRules sizing_rules;
  sizing_rules.chord_tolerance = kChordShareOfBound * max_deviation;
  sizing_rules.max_faces = params.max_faces > 0 ? params.max_faces : std::max(kMaxFacesFloor, kMaxFacesPerInputFace * mesh.n_faces());
  sizing_rules.size = params.size;
  std::optional<detail::SizingField> sizing;
  sizing.emplace(mesh, constraints, sizing_rules);
  result.sizing_faces = sizing->estimated_faces();
  detail::RemeshRules rules;
  rules.max_deviation = kRemeshShareOfBound * max_deviation;
  rules.target_min_angle_deg = params.target_min_angle_deg;
  // Splits come before collapses: where a CAD export's strips are narrower than the target, a
  // vertex is made at every strip and most are collapsed again (animation: 178,000 splits for
  // 7,000 faces), so the splits may go well past the field's faces before the collapses.
  rules.max_faces = kSplitHeadroom * sizing_rules.max_faces;
  rules.out_of_time = out_of_time;
  const TriMesh before = mesh;
  // The estimate can fall short (a thin part's wedges): splits stopped at the limit leave a
  // half-refined surface, so the field is coarsened and the remeshing run again from the input.
  detail::RemeshCounts counts;
  int crossing_refinements = 0;
  // The crossings are counted only where they are the reason: on a remeshing stopped half-way,
  // whose splits may have piled thousands of faces on one spot, the count could take minutes.
  const auto taken_back = [&](const std::string& guard, const std::string& reason,
                              std::optional<std::size_t> intersections) {
    result.remesh_crossing_refinements = crossing_refinements;
    const QualityTail remeshed = detail::measure_tail(mesh, params.target_min_angle_deg);
    TakenBack record{"enhance", guard, "remeshing", 1, reason + "; the input's own faces are enhanced instead",
                     {{"faces", static_cast<double>(mesh.n_faces())},
                      {"faces_below_target_angle", remeshed.under_target_fraction}},
                     {{"faces", static_cast<double>(before.n_faces())},
                      {"faces_below_target_angle", result.before.under_target_fraction}}};
    if (intersections) {
      record.before.push_back({"self_intersections", static_cast<double>(*intersections)});
      record.after.push_back({"self_intersections", static_cast<double>(allowed_intersections)});
    }
    result.taken_back.push_back(std::move(record));
    mesh = before;
    return false;
  };
  for (int attempt = 0;; ++attempt) {
    counts = detail::remesh_to_sizing(mesh, constraints, *sizing, rules);
    if (counts.stopped_by_time) {
      result.stopped_by_time_limit = true;
      return taken_back("time limit", "the time limit came before it was done", std::nullopt);
    }
    if (!counts.stopped_at_max_faces) {
      const MeshSoupView remeshed(mesh);
      const SelfIntersections crossings = find_self_intersections(remeshed);
      const std::size_t found = crossings.count;
      if (found <= allowed_intersections) break;
      // Graded from the corner edges, the finer faces can cross where two sheets pass close (bones'
      // cut curves, repaired; cow's): once more without that grading, as before it. A field the
      // corner edges asked nothing of would only repeat the same remeshing.
      if (sizing_rules.grade_from_corner_edges && sizing->corner_edge_demands() > 0) {
        result.taken_back.push_back({"enhance", "self-intersection", "grading from the corner edges", 1,
                                     "the remeshing graded from the corner edges crossed itself at " +
                                         std::to_string(found) + " face pairs; remeshed again without that grading",
                                     {{"self_intersections", static_cast<double>(found)}},
                                     {{"self_intersections", static_cast<double>(allowed_intersections)}}});
        sizing_rules.grade_from_corner_edges = false;
      } else if (crossing_refinements < kCrossingRefinements) {
        ++crossing_refinements;
        ask_finer_where_crossing(remeshed, crossings, sizing_rules.crossing_demands);
      } else {
        return taken_back("self-intersection",
                          "it made the surface cross itself at " + std::to_string(found) + " face pairs (the input: " +
                              std::to_string(allowed_intersections) + "), also after a remeshing finer where it crossed",
                          found);
      }
      mesh = before;
      sizing.emplace(mesh, constraints, sizing_rules);
      result.sizing_faces = sizing->estimated_faces();
      attempt = -1;
      continue;
    }
    if (attempt + 1 == kRemeshAttempts)
      return taken_back("face limit",
                        "its splits reached the face limit (" + std::to_string(rules.max_faces) + ") " +
                            std::to_string(kRemeshAttempts) + " times, the sizing field coarsened each time",
                        std::nullopt);
    mesh = before;
    sizing->coarsen(kCoarsening);
  }
  result.remesh_crossing_refinements = crossing_refinements;
  result.sizing_shortest = sizing->shortest() / diagonal;
  result.sizing_base = sizing->base_length() / diagonal;
  result.sizing_capped = sizing->capped();
  result.remeshed = true;
  std::shared_ptr<SizeField> field = sizing->field();
  field->move(shift);  // where the mesh is shifted back
  result.size_field = std::move(field);
  result.remesh_splits = counts.splits;
  result.remesh_collapses = counts.collapses;
  result.remesh_flips = counts.flips;
  return true;
}

}  // namespace

void check_enhance_params(const EnhanceParams& params) {
  const EnhanceParameters& info = enhance_parameters();
  if (params.max_deviation) check_parameter("enhance", info.max_deviation, *params.max_deviation);
  check_parameter("enhance", info.target_min_angle_deg, params.target_min_angle_deg);
  check_parameter("enhance", info.feature_angle_deg, params.feature_angle_deg);
  check_size_params(params.size);
  if (!(params.tail_weight >= 0) ||
      !(params.fidelity_weight >= 0) || !(params.flip_dihedral_deg >= 0 && params.flip_dihedral_deg < 90) ||
      !(params.max_face_change >= 0 && params.max_face_change <= 1) ||
      !std::isfinite(params.tail_k))
    throw InvalidInput("enhance: the statistic's constants are out of range (flip dihedral in [0, 90), weights >= 0)");
  if (!(params.time_limit_seconds == kAutomaticTimeLimit ||
        (params.time_limit_seconds >= 0 && std::isfinite(params.time_limit_seconds))))
    throw InvalidInput("enhance: time_limit_seconds must be -1 (automatic), 0 (none) or a positive number of seconds, not " +
                       parameter_text(params.time_limit_seconds));
}

double automatic_enhance_time_limit(std::size_t faces) {
  return kAutomaticTimeLimitScale *
         (kEnhanceTimeLimitFloorSeconds + kEnhanceTimeLimitPerFaceSeconds * static_cast<double>(faces));
}

EnhanceResult enhance(TriMesh& mesh, const TriangleSoup* reference, const EnhanceParams& params) {
  if (mesh.n_faces() == 0) throw InvalidInput("enhance: the mesh has no faces");
  check_enhance_params(params);
  const auto start = std::chrono::steady_clock::now();
  const ShiftedToOrigin near_origin(mesh);
  const TriangleSoup input = soup_from_mesh(mesh);
  const TriangleSoup moved_reference = reference ? near_origin.moved(*reference) : TriangleSoup();
  const TriangleSoup& surface = reference ? moved_reference : input;
  const double diagonal = bounding_box(surface).diagonal().norm();
  // The input's own distance from the reference: the automatic bound, and whether auto remeshes.
  const bool needs_own = !params.max_deviation || params.remesh == EnhanceRemesh::Auto;
  const double own = needs_own ? input_deviation(input, reference ? &surface : nullptr, diagonal) : 0;
  double relative_deviation = kLoosest;
  if (params.max_deviation)
    relative_deviation = *params.max_deviation;
  else if (own > kOnReference)
    relative_deviation = std::min(own, kLoosest);
  const double max_deviation = relative_deviation * diagonal;
  // Auto remeshes a tessellation that lies on its reference (a CAD export, a scan as it is), not
  // a simplified surface whose vertices the simplification placed off it (the decimated bunny's
  // remeshing crossed itself, was taken back, and cost 11 s).
  const QualityTail input_tail = detail::measure_tail(mesh, params.target_min_angle_deg);
  // A size the user set is followed wherever the input lies.
  const bool remeshing = params.remesh == EnhanceRemesh::On ||
                         (params.remesh == EnhanceRemesh::Auto &&
                          (params.size.any_set() ||
                           (own <= kOnReference && input_tail.under_target_fraction > EnhanceParams::kRemeshAbove)));
  // Remeshing, the edges between planes are creases too (surface_constraints.h); taken back, the
  // features are found again as for any other input.
  std::optional<detail::SurfaceConstraints> features;
  features.emplace(mesh, surface, params.feature_angle_deg, remeshing);
  const std::size_t allowed_intersections = find_self_intersections(input).count;
  const double min_angle_cosine = std::cos(params.target_min_angle_deg * M_PI / 180.0);
  // Ceres runs on one thread: with more, its cost sums depend on the thread count, so the LM steps,
  // and the output, did too (femur: 1 and 2 threads gave different meshes). Measured on bunny00
  // at 10 %: no slower (3.9-4.7 s against 4.7-5.6 s on 2 threads, a loaded machine); the
  // guards' closest-point queries around it still use TBB.
  const int threads = 1;

  EnhanceResult result;
  result.input_self_intersections = allowed_intersections;
  result.max_deviation = relative_deviation;
  result.before = input_tail;
  result.faces_before = mesh.n_faces();
  // The time limit grows with the faces worked on: the input's, or the sizing field's once known.
  const auto out_of_time = [&] {
    if (params.deadline.passed()) return true;
    const double limit = params.time_limit_seconds == kAutomaticTimeLimit
                           ? automatic_enhance_time_limit(std::max(result.faces_before, result.sizing_faces))
                           : params.time_limit_seconds;
    return limit > 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >= limit;
  };
  // The remeshing comes before the first round: its polls report no progress, but let a stop
  // requested through the progress callback (Ctrl-C, SIGTERM) end it.
  const auto remeshing_out_of_time = [&] {
    if (params.progress) params.progress(0.0);
    return out_of_time();
  };
  if (remeshing) {
    const auto remesh_start = std::chrono::steady_clock::now();
    const bool kept = remesh(mesh, *features, params, max_deviation, diagonal, near_origin.shift(), allowed_intersections,
                             remeshing_out_of_time, result);
    result.remesh_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - remesh_start).count();
    if (!kept) features.emplace(mesh, surface, params.feature_angle_deg, false);
  }
  detail::SurfaceConstraints& constraints = *features;
  for (const auto v : mesh.vertices()) {
    if (constraints.role(v) == detail::VertexRole::Line) ++result.line_vertices;
    if (constraints.role(v) == detail::VertexRole::Fixed) ++result.fixed_vertices;
  }
  // After remeshing, the rounds keep to the remeshing's share of the bound too: their guards
  // sample the faces (centroid, edge midpoints) and the reference (vertices, bent edges), and the
  // report's denser sampling measured up to 1.5 times what they allow on the CAD parts.
  const double round_deviation = result.remeshed ? kRemeshShareOfBound * max_deviation : max_deviation;
  // Each removed vertex takes two faces with it, each split adds two: the count stays within
  // max_face_change of the rounds' start either way.
  const auto face_budget = static_cast<std::size_t>(params.max_face_change * static_cast<double>(mesh.n_faces()));
  const std::size_t removal_budget = face_budget / 2;
  // The remeshed surface is a new tessellation: points along the reference's bent edges are
  // probed as well as its vertices, at a quarter of the new median edge.
  const std::vector<Vec3> probes =
      detail::reference_probes(surface, result.remeshed ? kProbesPerEdge * detail::median_edge_length(mesh) : 0);
  const std::vector<TriangleBvh::Hit> coverage = detail::reference_coverage(mesh, probes);
  std::vector<double> allowed_distance;  // of each probe to the mesh
  for (const auto& hit : coverage)
    allowed_distance.push_back(std::max(round_deviation, std::sqrt(hit.squared_distance)));
  QualityTail best = result.before, last = result.before;
  struct {
    std::size_t rounds = 0, edits = 0, worst_intersections = 0;
  } cleanup_taken_back;  // rounds whose flips, collapses and splits made the surface cross itself
  detail::UndoneMoves undone;
  std::size_t flips_made = 0, cap_flips_made = 0, removed_vertices = 0, split_edges = 0;
  TriMesh best_mesh = mesh;
  int stale_rounds = 0;
  for (std::size_t round = 1; round <= params.iterations; ++round) {
    if (out_of_time()) {
      result.stopped_by_time_limit = true;
      break;
    }
    result.rounds = round;
    if (params.flips) {
      const TriMesh before_cleanup = mesh;
      const detail::CleanupRules rules{params.flip_dihedral_deg, round_deviation, min_angle_cosine};
      const std::size_t flips = detail::flip_for_angles(mesh, constraints, rules);
      const std::size_t cap_flips = detail::flip_caps(mesh, constraints, rules);
      const std::size_t removed = detail::collapse_for_angles(mesh, constraints, rules, removal_budget - removed_vertices);
      const std::size_t split_budget = (face_budget + 2 * (removed_vertices + removed)) / 2 - split_edges;
      const std::size_t splits = detail::split_for_angles(mesh, constraints, rules, split_budget);
      const std::size_t edits = flips + cap_flips + removed + splits;
      const std::size_t found = edits > 0 ? find_self_intersections(MeshSoupView(mesh)).count : 0;
      if (found > allowed_intersections) {
        mesh = before_cleanup;
        ++cleanup_taken_back.rounds;
        cleanup_taken_back.edits += edits;
        cleanup_taken_back.worst_intersections = std::max(cleanup_taken_back.worst_intersections, found);
      } else {
        flips_made += flips;
        cap_flips_made += cap_flips;
        removed_vertices += removed;
        split_edges += splits;
      }
    }
    const Points before = points_of(mesh);
    const detail::RelocationWeights weights{detail::tail_weights(mesh, params), params.fidelity_weight};
    const detail::MoveGuards guards(mesh, constraints, probes, allowed_distance, allowed_intersections, round_deviation);
    const std::vector<Vec3> moved = detail::relocate_on_surface(mesh, constraints, weights, threads);
    for (const auto v : mesh.vertices()) {
      const std::size_t i = static_cast<std::size_t>(v.idx());
      if (constraints.role(v) != detail::VertexRole::Fixed && moved[i] != to_eigen(before[i]))
        mesh.set_point(v, to_openmesh(constraints.project(v, moved[i])));
    }
    fit_surface_vertices(mesh, constraints, min_angle_cosine, &before);
    undone += guards.enforce(mesh);
    if (params.progress) params.progress(static_cast<double>(round) / static_cast<double>(params.iterations));
    const QualityTail now = detail::measure_tail(mesh, params.target_min_angle_deg);
    last = now;
    if (!detail::improves(now, best, params.target_min_angle_deg)) {
      if (++stale_rounds == kStaleRounds) break;
      continue;  // from this round's mesh: its flips and splits may open the way
    }
    stale_rounds = 0;
    best = now;
    best_mesh = mesh;
    result.kept_round = round;
    result.flips = flips_made;
    result.cap_flips = cap_flips_made;
    result.removed_vertices = removed_vertices;
    result.split_edges = split_edges;
  }
  mesh = best_mesh;
  // The kept round's fit ran before its guards took moves back; one more fit settles the result,
  // under the same guards as a round's moves (a fit along the normals can sharpen an edge into a
  // fold as well as make the surface cross itself).
  const detail::MoveGuards final_guards(mesh, constraints, probes, allowed_distance, allowed_intersections, round_deviation);
  fit_surface_vertices(mesh, constraints, min_angle_cosine);
  undone += final_guards.enforce(mesh);
  require_finite_points(mesh, "enhance");
  result.after = detail::measure_tail(mesh, params.target_min_angle_deg);
  result.undone_moves = undone.total();
  if (cleanup_taken_back.rounds > 0)
    result.taken_back.push_back(
        {"enhance", "self-intersection", "rounds' flips, collapses and splits", cleanup_taken_back.rounds,
         std::to_string(cleanup_taken_back.edits) + " edits made the surface cross itself; each round went on from its start",
         {{"self_intersections", static_cast<double>(cleanup_taken_back.worst_intersections)}},
         {{"self_intersections", static_cast<double>(allowed_intersections)}}});
  if (undone.total() > 0)
    result.taken_back.push_back(
        {"enhance", "move guards", "vertex moves", undone.total(),
         std::to_string(undone.bad_faces) + " turned, folded or pulled a face past the bound, " +
             std::to_string(undone.uncovering) + " uncovered the reference, " + std::to_string(undone.intersections) +
             " made the surface cross itself",
         {{"vertex_moves", static_cast<double>(undone.moved)}},
         {{"vertex_moves", static_cast<double>(undone.moved - undone.total())}}});
  if (result.kept_round == 0 && result.rounds > 0)
    result.taken_back.push_back(
        {"enhance", "no gain", "rounds", result.rounds,
         "no round improved the faces' angle statistic (the tail of their quality); the surface the rounds began from is kept",
         {{"faces_below_target_angle", last.under_target_fraction}, {"min_angle_deg", last.min_angle_deg}},
         {{"faces_below_target_angle", best.under_target_fraction}, {"min_angle_deg", best.min_angle_deg}}});
  result.faces_after = mesh.n_faces();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace meshprep
