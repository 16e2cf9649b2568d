#include "meshprep/preprocess/enhance.h"

#include "enhance_defaults.h"
#include "intersection_guard.h"
#include "quality_tail.h"
#include "surface_constraints.h"
#include "surface_fit.h"
#include "surface_relocation.h"
#include "topology_cleanup.h"

#include "meshprep/core/errors.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/triangle_bvh.h"

#include <tbb/parallel_for.h>

#include <array>
#include <chrono>
#include <cmath>
#include <thread>

namespace meshprep {

EnhanceParams::EnhanceParams()
    : tail_k(detail::enhance_defaults::kTailK),
      tail_weight(detail::enhance_defaults::kTailWeight),
      fidelity_weight(detail::enhance_defaults::kFidelityWeight),
      flip_dihedral_deg(detail::enhance_defaults::kFlipDihedralDeg) {}

namespace {

using Points = std::vector<TriMesh::Point>;
const double kTurnCosine = std::cos(60.0 * M_PI / 180.0);  // largest normal turn of a face in one round

Points points_of(const TriMesh& mesh) { return Points(mesh.points(), mesh.points() + mesh.n_vertices()); }

// The face's corners at `at` (by vertex index), or where they are now.
std::array<Vec3, 3> corners_of(const TriMesh& mesh, TriMesh::FaceHandle f, const Points* at = nullptr) {
  std::array<Vec3, 3> p;
  int k = 0;
  for (const auto v : mesh.fv_range(f)) p[static_cast<std::size_t>(k++)] = to_eigen(at ? (*at)[static_cast<std::size_t>(v.idx())] : mesh.point(v));
  return p;
}

Vec3 normal_of(const std::array<Vec3, 3>& p) { return (p[1] - p[0]).cross(p[2] - p[0]); }

Vec3 centroid_of(const TriMesh& mesh, TriMesh::FaceHandle f) {
  const auto p = corners_of(mesh, f);
  return (p[0] + p[1] + p[2]) / 3.0;
}

// How far a face is from the reference: the largest distance of its centroid and edge midpoints
// (its corners are on the reference).
double face_deviation(const std::array<Vec3, 3>& p, const detail::SurfaceConstraints& constraints) {
  double worst = 0;
  for (const Vec3& q : {Vec3((p[0] + p[1] + p[2]) / 3.0), Vec3(0.5 * (p[0] + p[1])), Vec3(0.5 * (p[1] + p[2])), Vec3(0.5 * (p[2] + p[0]))})
    worst = std::max(worst, constraints.closest_on_reference(q).squared_distance);
  return std::sqrt(worst);
}

// Faces that turned by more than 60 degrees in this round (or folded over) and faces carried
// farther from the reference than the bound allows (face_deviation, unless they already were):
// their vertices go back to `before`, then the faces around those vertices are checked again,
// until none is left. Each sweep measures its faces in parallel and puts vertices back in face order.
std::size_t undo_bad_moves(TriMesh& mesh, const detail::SurfaceConstraints& constraints, const Points& before,
                           double max_deviation) {
  auto moved = [&](TriMesh::VertexHandle v) { return mesh.point(v) != before[static_cast<std::size_t>(v.idx())]; };
  std::vector<TriMesh::FaceHandle> suspects;
  for (const auto f : mesh.faces())
    for (const auto v : mesh.fv_range(f))
      if (moved(v)) {
        suspects.push_back(f);
        break;
      }
  std::size_t undone = 0;
  std::vector<char> queued(mesh.n_faces(), 0);
  while (!suspects.empty()) {
    std::vector<char> bad(suspects.size(), 0);
    tbb::parallel_for(std::size_t(0), suspects.size(), [&](std::size_t k) {
      const auto old_corners = corners_of(mesh, suspects[k], &before), corners = corners_of(mesh, suspects[k]);
      const Vec3 n0 = normal_of(old_corners), n1 = normal_of(corners);
      if (n0.dot(n1) <= kTurnCosine * n0.norm() * n1.norm()) {
        bad[k] = 1;
        return;
      }
      const double deviation = face_deviation(corners, constraints);
      bad[k] = deviation > max_deviation && deviation > face_deviation(old_corners, constraints);
    });
    std::vector<TriMesh::VertexHandle> reverted;
    for (std::size_t k = 0; k < suspects.size(); ++k) {
      queued[static_cast<std::size_t>(suspects[k].idx())] = 0;
      if (!bad[k]) continue;
      for (const auto v : mesh.fv_range(suspects[k]))
        if (moved(v)) {
          mesh.set_point(v, before[static_cast<std::size_t>(v.idx())]);
          reverted.push_back(v);
        }
    }
    undone += reverted.size();
    suspects.clear();
    for (const auto v : reverted)
      for (const auto f : mesh.vf_range(v))
        if (!queued[static_cast<std::size_t>(f.idx())]) {
          queued[static_cast<std::size_t>(f.idx())] = 1;
          suspects.push_back(f);
        }
  }
  return undone;
}

// Distance of every reference vertex to the mesh, and the face where it is reached.
std::vector<TriangleBvh::Hit> reference_coverage(const TriMesh& mesh, const TriangleSoup& reference) {
  const TriangleSoup soup = soup_from_mesh(mesh);
  const TriangleBvh bvh(soup);
  std::vector<TriangleBvh::Hit> hits(reference.points.size());
  tbb::parallel_for(std::size_t(0), hits.size(), [&](std::size_t i) { hits[i] = bvh.closest_point(reference.points[i]); });
  return hits;
}

// The other direction of the deviation bound: a reference vertex the mesh has moved away from
// (farther than the bound, and than the input was) sends the vertices of its nearest face, now and
// at the start of the round, back. Only a reference vertex whose nearest face moved can be farther
// than it was; the others are not measured again. The mesh's topology is that of the start of the
// round.
std::size_t undo_uncovering_moves(TriMesh& mesh, const TriangleSoup& reference, const Points& before,
                                  const std::vector<TriangleBvh::Hit>& coverage_before,
                                  const std::vector<double>& allowed_distance) {
  auto moved = [&](std::size_t face) {
    for (const auto v : mesh.fv_range(TriMesh::FaceHandle(static_cast<int>(face))))
      if (mesh.point(v) != before[static_cast<std::size_t>(v.idx())]) return true;
    return false;
  };
  std::vector<std::size_t> suspects;
  for (std::size_t i = 0; i < coverage_before.size(); ++i)
    if (moved(coverage_before[i].face)) suspects.push_back(i);
  const TriangleSoup soup = soup_from_mesh(mesh);
  const TriangleBvh bvh(soup);
  std::vector<TriangleBvh::Hit> coverage(suspects.size());
  tbb::parallel_for(std::size_t(0), suspects.size(), [&](std::size_t k) { coverage[k] = bvh.closest_point(reference.points[suspects[k]]); });
  std::size_t undone = 0;
  for (std::size_t k = 0; k < suspects.size(); ++k) {
    const std::size_t i = suspects[k];
    if (coverage[k].squared_distance <= allowed_distance[i] * allowed_distance[i]) continue;
    for (const std::size_t face : {coverage[k].face, coverage_before[i].face})
      for (const auto v : mesh.fv_range(TriMesh::FaceHandle(static_cast<int>(face)))) {
        const auto& old = before[static_cast<std::size_t>(v.idx())];
        if (mesh.point(v) == old) continue;
        mesh.set_point(v, old);
        ++undone;
      }
  }
  return undone;
}

std::vector<TriangleBvh::Hit> centroid_hits(const TriMesh& mesh, const detail::SurfaceConstraints& constraints) {
  std::vector<TriangleBvh::Hit> hits(mesh.n_faces());
  tbb::parallel_for(std::size_t(0), hits.size(), [&](std::size_t i) {
    hits[i] = constraints.closest_on_reference(centroid_of(mesh, TriMesh::FaceHandle(static_cast<int>(i))));
  });
  return hits;
}

// One sweep of the least-squares fit to the reference along the normals (surface_fit.h): the
// charts and the projection put vertices on the surface, the fit puts the faces on it. Vertices on
// features stay on their lines.
void fit_surface_vertices(TriMesh& mesh, const detail::SurfaceConstraints& constraints, double min_angle_cosine) {
  const Points before = points_of(mesh);
  detail::fit_to_reference(mesh, constraints.reference_bvh(), min_angle_cosine);
  for (const auto v : mesh.vertices())
    if (constraints.role(v) != detail::VertexRole::Surface) mesh.set_point(v, before[static_cast<std::size_t>(v.idx())]);
}

void check(const EnhanceParams& params, const TriMesh& mesh) {
  if (mesh.n_faces() == 0) throw InvalidInput("enhance: the mesh has no faces");
  if (!(params.max_deviation > 0) || !(params.target_min_angle_deg > 0 && params.target_min_angle_deg < 60) ||
      !(params.feature_angle_deg > 0 && params.feature_angle_deg <= 180) || !(params.tail_weight >= 0) ||
      !(params.fidelity_weight >= 0) || !(params.flip_dihedral_deg >= 0 && params.flip_dihedral_deg < 90) ||
      !(params.max_face_change >= 0 && params.max_face_change <= 1) ||
      !std::isfinite(params.tail_k))
    throw InvalidInput("enhance: parameters out of range (max deviation > 0, target angle in (0, 60), feature angle in "
                       "(0, 180], flip dihedral in [0, 90), weights >= 0)");
}

}  // namespace

EnhanceResult enhance(TriMesh& mesh, const TriangleSoup* reference, const EnhanceParams& params) {
  check(params, mesh);
  const auto start = std::chrono::steady_clock::now();
  const TriangleSoup input = soup_from_mesh(mesh);
  const TriangleSoup& surface = reference ? *reference : input;
  const double max_deviation = params.max_deviation * bounding_box(surface).diagonal().norm();
  const detail::SurfaceConstraints constraints(mesh, surface, params.feature_angle_deg);
  const std::size_t allowed_intersections = find_self_intersections(input).count;
  // Each removed vertex takes two faces with it.
  const auto removal_budget = static_cast<std::size_t>(params.max_face_change * static_cast<double>(mesh.n_faces()) / 2);
  const double min_angle_cosine = std::cos(params.target_min_angle_deg * M_PI / 180.0);
  const int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

  EnhanceResult result;
  for (const auto v : mesh.vertices()) {
    if (constraints.role(v) == detail::VertexRole::Line) ++result.line_vertices;
    if (constraints.role(v) == detail::VertexRole::Fixed) ++result.fixed_vertices;
  }
  result.before = detail::measure_tail(mesh, params.target_min_angle_deg);
  std::vector<double> allowed_distance;  // of each reference vertex to the mesh
  for (const auto& hit : reference_coverage(mesh, surface))
    allowed_distance.push_back(std::max(max_deviation, std::sqrt(hit.squared_distance)));
  QualityTail best = result.before;
  std::size_t flips_made = 0, removed_vertices = 0;
  TriMesh best_mesh = mesh;
  for (std::size_t round = 1; round <= params.iterations; ++round) {
    result.rounds = round;
    if (params.flips) {
      const TriMesh before_cleanup = mesh;
      const detail::CleanupRules rules{params.flip_dihedral_deg, max_deviation, min_angle_cosine};
      const std::size_t flips = detail::flip_for_angles(mesh, constraints, rules);
      const std::size_t removed = detail::collapse_for_angles(mesh, constraints, rules, removal_budget - removed_vertices);
      if (find_self_intersections(soup_from_mesh(mesh)).count > allowed_intersections) {
        mesh = before_cleanup;
      } else {
        flips_made += flips;
        removed_vertices += removed;
      }
    }
    const Points before = points_of(mesh);
    detail::RelocationWeights weights{detail::tail_weights(mesh, params), params.fidelity_weight, centroid_hits(mesh, constraints)};
    const std::vector<TriangleBvh::Hit> coverage_before = reference_coverage(mesh, surface);
    const std::vector<Vec3> moved = detail::relocate_on_surface(mesh, constraints, weights, threads);
    for (const auto v : mesh.vertices()) {
      const std::size_t i = static_cast<std::size_t>(v.idx());
      if (constraints.role(v) != detail::VertexRole::Fixed && moved[i] != to_eigen(before[i]))
        mesh.set_point(v, to_openmesh(constraints.project(v, moved[i])));
    }
    fit_surface_vertices(mesh, constraints, min_angle_cosine);
    // Every guard only puts vertices back where the round found them; the next guard may then find
    // a face that is half old, half new, so they run again until none puts anything back.
    for (int pass = 0; pass < 8; ++pass) {
      std::size_t undone = undo_bad_moves(mesh, constraints, before, max_deviation);
      undone += undo_uncovering_moves(mesh, surface, before, coverage_before, allowed_distance);
      undone += detail::undo_new_intersections(mesh, before, allowed_intersections);
      result.undone_moves += undone;
      if (undone == 0) break;
    }
    if (params.progress) params.progress(static_cast<double>(round) / static_cast<double>(params.iterations));
    const QualityTail now = detail::measure_tail(mesh, params.target_min_angle_deg);
    if (!detail::improves(now, best)) break;
    best = now;
    best_mesh = mesh;
    result.kept_round = round;
    result.flips = flips_made;
    result.removed_vertices = removed_vertices;
  }
  mesh = best_mesh;
  // The kept round's fit ran before its guards took moves back; one more fit settles the result.
  const Points fitted_from = points_of(mesh);
  fit_surface_vertices(mesh, constraints, min_angle_cosine);
  result.undone_moves += detail::undo_new_intersections(mesh, fitted_from, allowed_intersections);
  result.after = detail::measure_tail(mesh, params.target_min_angle_deg);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace meshprep
