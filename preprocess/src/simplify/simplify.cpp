#include "meshprep/preprocess/simplify/simplify.h"
#include "meshprep/preprocess/simplify/simplify_parameters.h"

#include "simplify/collapse_quadrics.h"
#include "simplify/edge_collapse.h"
#include "simplify/reference_relaxation.h"
#include "simplify/shape_polish.h"
#include "shared/spatial_order.h"
#include "shared/surface_fit.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/finite_points.h"
#include "meshprep/quality/height_field.h"
#include "meshprep/core/origin_shift.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/triangle_bvh.h"

#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <utility>

namespace meshprep {
namespace {

// The relaxation between collapses may move a vertex as far (quadric RMS estimate) as this
// multiple of the RMS error the collapses left (typical_error): a tolerance that follows the
// achieved fidelity, so a CAD part simplified almost exactly (fandisk) is barely touched while an
// organic scan gets room to even its triangles out. The relaxation on the original surface keeps
// its faces within the same multiple. The final polish gets less room: bunny00 at 10 % has RMS
// distance 1.58e-4 with 1.3, 1.54e-4 with 0.5, radius ratio p95 1.83 and 1.88
// (docs/simplification.md).
constexpr double kReshapeTolerance = 1.3;
constexpr double kFinalPolishTolerance = 0.5;
constexpr int kPolishSweeps = 3;
// Restarts with a tighter error cap where the output intersects itself (decimate_with_guards).
constexpr int kRetries = 6;

// Status flags for collapses. Not the halfedges': no one reads them, and every status() inside
// Debian's OpenMesh (built with its assertions on) builds and compares a type name, two more of
// them per collapse and per loop removed.
void request_collapse_attributes(TriMesh& mesh) {
  mesh.request_vertex_status();
  mesh.request_edge_status();
  mesh.request_face_status();
}

std::size_t target_of(const TriMesh& mesh, const SimplifyParams& params) {
  if (params.target_faces > 0) return params.target_faces;
  check_parameter("simplify", simplify_parameters().keep_ratio, params.keep_ratio);
  return static_cast<std::size_t>(std::llround(params.keep_ratio * static_cast<double>(mesh.n_faces())));
}

// Garland & Heckbert 1997 quadrics as OpenMesh implements them; normal flips forbidden.
// (Face normals for its normal-flip module only: our own collapses compute what they test, and
// the normals were 24 bytes a face of the peak.)
void decimate_quadric(TriMesh& mesh, std::size_t target) {
  mesh.request_face_normals();
  mesh.update_face_normals();
  using Decimater = OpenMesh::Decimater::DecimaterT<TriMesh>;
  Decimater decimater(mesh);
  OpenMesh::Decimater::ModQuadricT<TriMesh>::Handle quadric;
  OpenMesh::Decimater::ModNormalFlippingT<TriMesh>::Handle no_flips;
  decimater.add(quadric);
  decimater.add(no_flips);
  decimater.module(quadric).unset_max_err();
  decimater.initialize();
  decimater.decimate_to_faces(0, target);
}

// RMS over the vertices of their quadric's plane distance: how far the collapses have moved the surface.
double typical_error(const TriMesh& mesh, const std::vector<detail::Quadric>& quadrics) {
  double sum = 0;
  std::size_t count = 0;
  for (const auto v : mesh.vertices()) {
    if (mesh.status(v).deleted()) continue;
    const double e = detail::rms_plane_distance(quadrics[static_cast<std::size_t>(v.idx())], to_eigen(mesh.point(v)));
    sum += e * e;
    ++count;
  }
  return count ? std::sqrt(sum / static_cast<double>(count)) : 0.0;
}

// One simplification of `mesh` (not garbage-collected) under the per-vertex error caps; returns
// the vertex quadrics; error_cap and merged_into as collapse_edges.
std::vector<detail::Quadric> decimate_once(TriMesh& mesh, const SimplifyParams& params, const TriangleSoup& original,
                                           const std::vector<double>& error_cap, std::vector<int>& merged_into,
                                           SimplifyResult& result) {
  const detail::CollapseScales scales = detail::measure_scales(mesh, params.cost);
  std::vector<detail::Quadric> quadrics = detail::vertex_quadrics(mesh, scales.edge_length);
  const double min_angle_cosine = params.min_angle_deg > 0 ? std::cos(params.min_angle_deg * M_PI / 180.0) : 1.0;
  // The bending cost's placements minimise the error estimate: only the shape tail moves off
  // them, and within a tighter tolerance at the end. The distance cost's (on the local RBF
  // surface, not the error's minimum) all relax, as far as between collapses: with the tail alone
  // the icosphere at 10 % kept edges long enough for a Hausdorff distance of 0.0208 (0.0147 with all).
  const bool keep_placements = params.cost == CollapseCost::Bending;
  const detail::ShapeTail tail_of_shape{detail::ShapeTail().ratio, min_angle_cosine};
  const detail::ShapeTail* tail = keep_placements ? &tail_of_shape : nullptr;
  // An open height field (a terrain) stays one, no steeper than it was, so that it can still be
  // extruded into a block (the bundled terrain at 3,000 faces folded over before).
  const detail::HeightField field = detail::height_field_of(mesh, height_field_up(original).value_or(Vec3::Zero()));
  // Patches of thin input triangles allow no collapse above the angle bound: relaxing their
  // vertices each time the face count halves frees them (the 4.8 M-face subdivided bunny to 7,540
  // faces: Hausdorff 1.1e-2 -> 1.9e-3), and where every remaining collapse would make a face too
  // thin, every vertex and flips as well (bunny00 to 500 faces stopped at 1,188).
  const auto reshape = [&](detail::Reshape how) {
    const bool stuck = how == detail::Reshape::FlipAndRelax;
    const detail::PolishCounts polish = detail::polish_shape(
        mesh, quadrics, kReshapeTolerance * typical_error(mesh, quadrics), stuck, stuck ? nullptr : tail, field);
    result.polish_flips += polish.flips;
    result.polish_moves += polish.moves;
    return polish.flips + polish.moves > 0;
  };
  detail::collapse_edges(mesh, result.target_faces, params, scales, quadrics, error_cap, merged_into, result, field,
                         params.polish ? detail::ReshapeCallback(reshape) : detail::ReshapeCallback());
  if (!params.polish) return quadrics;
  const TriangleBvh reference(original);
  const double tolerance = (keep_placements ? kFinalPolishTolerance : kReshapeTolerance) * typical_error(mesh, quadrics);
  for (int sweep = 0; sweep < kPolishSweeps; ++sweep) {
    const detail::PolishCounts polish = detail::polish_shape(mesh, quadrics, tolerance, true, tail, field);
    result.polish_flips += polish.flips;
    result.polish_moves += polish.moves;
  }
  result.polish_moves +=
      detail::relax_on_reference(mesh, reference, kReshapeTolerance * typical_error(mesh, quadrics), min_angle_cosine, field);
  // One fit at the end does what one after every sweep did (bunny00, 10 % and 30 %: the same
  // RMS and Hausdorff distances to 3 digits) at a third of the closest-point queries.
  result.fit_moves = detail::fit_to_reference(mesh, reference, min_angle_cosine, field);
  return quadrics;
}

// The surviving vertex an input vertex was collapsed into (following the chain of merges).
int survivor(std::vector<int>& merged_into, int v) {
  int root = v;
  while (merged_into[static_cast<std::size_t>(root)] != root) root = merged_into[static_cast<std::size_t>(root)];
  while (merged_into[static_cast<std::size_t>(v)] != root) v = std::exchange(merged_into[static_cast<std::size_t>(v)], root);
  return root;
}

// Halve the error allowed around the crossings (`output` is soup_from_mesh(simplified)): every
// input vertex merged into a corner of a crossing face (or, grow > 0, into a vertex up to `grow` rings from one) may now only be
// collapsed to half the error its survivor reached.
void tighten_around_crossings(const TriMesh& simplified, const TriangleSoup& output,
                              const std::vector<detail::Quadric>& quadrics, const SelfIntersections& crossings,
                              int grow, std::vector<int>& merged_into, std::vector<double>& error_cap) {
  std::vector<int> soup_to_mesh;  // soup_from_mesh numbers the surviving vertices in order
  for (const auto v : simplified.all_vertices())
    if (!simplified.status(v).deleted()) soup_to_mesh.push_back(v.idx());
  std::vector<char> hot(simplified.n_vertices(), 0);
  for (const auto& [f, g] : crossings.pairs)
    for (const std::size_t face : {f, g})
      for (const std::uint32_t corner : output.triangles[face]) hot[static_cast<std::size_t>(soup_to_mesh[corner])] = 1;
  for (int ring = 0; ring < grow; ++ring) {
    std::vector<char> next = hot;
    for (const auto v : simplified.vertices())
      if (hot[static_cast<std::size_t>(v.idx())])
        for (const auto w : simplified.vv_range(v)) next[static_cast<std::size_t>(w.idx())] = 1;
    hot.swap(next);
  }
  for (std::size_t v = 0; v < error_cap.size(); ++v) {
    const auto s = static_cast<std::size_t>(survivor(merged_into, static_cast<int>(v)));
    if (!hot[s]) continue;
    const double reached = detail::rms_plane_distance(quadrics[s], to_eigen(simplified.point(TriMesh::VertexHandle(static_cast<int>(s)))));
    error_cap[v] = std::min(error_cap[v], 0.5 * reached);
  }
}

// The guards do not test for self-intersections (a dynamic BVH per collapse would cost more
// than the collapse): the output is checked instead, and where it intersects itself while the
// input did not, the simplification starts again from the input with half the error allowed
// where the crossing faces came from (one more ring of them each time). Two close sheets then
// simplify until their error fits between them.
void decimate_with_guards(TriMesh& mesh, const SimplifyParams& params, SimplifyResult& result) {
  const TriangleSoup original = detail::in_spatial_order(soup_from_mesh(mesh));
  std::vector<double> error_cap(original.points.size(), std::numeric_limits<double>::infinity());
  std::size_t first_crossings = 0;
  for (int attempt = 0;; ++attempt) {
    mesh = mesh_from_soup(original);  // (again on a restart: no copy of the input is kept)
    request_collapse_attributes(mesh);
    std::vector<int> merged_into(mesh.n_vertices());
    std::iota(merged_into.begin(), merged_into.end(), 0);
    const std::vector<detail::Quadric> quadrics = decimate_once(mesh, params, original, error_cap, merged_into, result);
    const TriangleSoup output = soup_from_mesh(mesh);
    const SelfIntersections crossings = find_self_intersections(output);
    if (attempt == 0) first_crossings = crossings.count;
    if (crossings.count == 0 || attempt == kRetries) {
      if (attempt > 0)
        result.taken_back.push_back(
            {"simplify", "self-intersection", "decimations", static_cast<std::size_t>(attempt),
             "the output crossed itself where the input did not; each time the decimation started again from the "
             "input with half the error allowed around the crossings",
             {{"self_intersections", static_cast<double>(first_crossings)}},
             {{"self_intersections", static_cast<double>(crossings.count)}}});
      return;
    }
    if (attempt == 0 && find_self_intersections(original, 1).count > 0) return;  // not ours to fix
    tighten_around_crossings(mesh, output, quadrics, crossings, attempt, merged_into, error_cap);
    const SimplifyResult counters = result;
    result = SimplifyResult{};
    result.faces_before = counters.faces_before;
    result.target_faces = counters.target_faces;
    result.intersection_retries = counters.intersection_retries + 1;
  }
}

// One reduction to the target with the chosen cost.
SimplifyResult reduce(TriMesh& mesh, const SimplifyParams& params) {
  SimplifyResult result;
  result.faces_before = mesh.n_faces();
  result.target_faces = target_of(mesh, params);
  request_collapse_attributes(mesh);
  const auto start = std::chrono::steady_clock::now();
  if (result.target_faces < result.faces_before) {
    if (params.cost == CollapseCost::Quadric)
      decimate_quadric(mesh, result.target_faces);
    else
      decimate_with_guards(mesh, params, result);
  }
  mesh.garbage_collection();  // (the quadric baseline's deleted elements)
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.faces_after = mesh.n_faces();
  return result;
}

void check(const TriMesh& mesh, const SimplifyParams& params) {
  if (mesh.n_faces() == 0) throw InvalidInput("the mesh has no faces to simplify");
  // NaN fails the range (a NaN angle bound would switch the guard off silently).
  check_parameter("simplify", simplify_parameters().min_angle_deg, params.min_angle_deg);
  if (!(params.max_error >= 0 && std::isfinite(params.max_error)))
    throw InvalidInput("the maximum error must be a finite number >= 0");
}

}  // namespace

SimplifyResult simplify(TriMesh& mesh, const SimplifyParams& params) {
  check(mesh, params);
  const ShiftedToOrigin near_origin(mesh);  // quadrics square the coordinates
  SimplifyResult result = reduce(mesh, params);
  require_finite_points(mesh, "simplify");
  if (params.progress) params.progress(1.0);
  result.reached_target = reaches_target(result.faces_after, result.target_faces);
  return result;
}

bool reaches_target(std::size_t faces, std::size_t target) {
  const double slack = 0.01 * static_cast<double>(target);
  return std::abs(static_cast<double>(faces) - static_cast<double>(target)) <= std::max(slack, 1.0);
}

std::size_t simplify_target(const TriMesh& mesh, const SimplifyParams& params) {
  check(mesh, params);
  return target_of(mesh, params);
}

}  // namespace meshprep
