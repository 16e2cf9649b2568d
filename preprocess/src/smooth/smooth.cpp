#include "meshprep/preprocess/smooth/smooth.h"

#include "shared/intersection_guard.h"
#include "smooth/laplacian_smoothing.h"
#include "smooth/rbf_smoothing.h"

#include "meshprep/core/soup_view.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/finite_points.h"
#include "meshprep/core/origin_shift.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/triangle_metrics.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace meshprep {
namespace {

bool closed(const TriMesh& mesh) {
  for (const auto v : mesh.vertices())
    if (mesh.is_boundary(v)) return false;
  return mesh.n_faces() > 0;
}

double volume(const TriMesh& mesh) { return signed_volume(MeshSoupView(mesh)); }

// --preserve-volume: the enclosed volume V(t) of the surface offset by t along its (area-weighted)
// vertex normals grows by about t x area; Newton steps on t bring it back to the input's volume
// without moving any vertex relative to its neighbours (no noise comes back).
void restore_volume(TriMesh& mesh, double target) {
  mesh.request_vertex_normals();
  for (int step = 0; step < 4; ++step) {
    const double now = volume(mesh);
    if (std::abs(now - target) <= 1e-9 * std::abs(target)) break;
    mesh.update_face_normals();
    mesh.update_vertex_normals();
    double area = 0;
    for (const auto f : mesh.faces()) area += mesh.calc_face_area(f);
    const double sign = target > 0 ? 1.0 : -1.0;  // outward normals give a positive volume
    const double offset = sign * (target - now) / area;
    for (const auto v : mesh.vertices()) mesh.set_point(v, mesh.point(v) + offset * mesh.normal(v));
  }
  mesh.release_vertex_normals();
}

// The vertices whose position differs from `before`.
std::size_t count_moved(const TriMesh& mesh, const std::vector<TriMesh::Point>& before) {
  std::size_t moved = 0;
  for (const auto v : mesh.vertices()) moved += mesh.point(v) != before[static_cast<std::size_t>(v.idx())];
  return moved;
}

}  // namespace

SmoothResult smooth(TriMesh& mesh, const SmoothParams& params) {
  if (params.method == SmoothMethod::Rbf && params.neighbors < 13)
    throw InvalidInput("smooth: at least 13 neighbours are needed (the local cubic height map has 10 terms)");
  if (!(params.smoothing >= 0) || !(params.feature_angle_deg > 0 && params.feature_angle_deg <= 180) ||
      !(params.relaxation >= 0 && params.relaxation <= 1))
    throw InvalidInput("smooth: the smoothing must be >= 0, the relaxation in [0, 1] and the feature angle in (0, 180] degrees");
  const auto start = std::chrono::steady_clock::now();
  const ShiftedToOrigin near_origin(mesh);
  SmoothResult result;
  const std::vector<TriMesh::Point> before(mesh.points(), mesh.points() + mesh.n_vertices());
  const bool is_closed = closed(mesh);
  const bool keep_volume = params.preserve_volume && is_closed;
  const TriangleSoup input = soup_from_mesh(mesh);
  if (is_closed) result.volume_before = signed_volume(input);

  // The guard allows the crossings the input had; they are counted only when a step leaves one.
  const auto input_intersections = [&] {
    if (!result.input_self_intersections) result.input_self_intersections = find_self_intersections(input).count;
    return *result.input_self_intersections;
  };
  std::size_t moved_vertices = 0;  // over the steps, for the guard's record
  if (params.method == SmoothMethod::Taubin) {
    taubin_smooth(mesh, params.iterations);
  } else if (params.method == SmoothMethod::Laplace) {
    laplace_smooth(mesh, params.iterations);
  } else {
    for (std::size_t i = 0; i < params.iterations; ++i) {
      RbfIterationCounts counts;
      const std::vector<TriMesh::Point> start_of_step(mesh.points(), mesh.points() + mesh.n_vertices());
      const std::vector<Vec3> moved = rbf_smoothing_step(mesh, params, counts);
      for (const auto v : mesh.vertices()) mesh.set_point(v, to_openmesh(moved[static_cast<std::size_t>(v.idx())]));
      moved_vertices += count_moved(mesh, start_of_step);
      result.undone_vertices += detail::undo_new_intersections(mesh, start_of_step, input_intersections);
      result.feature_line_vertices = counts.feature_line;
      result.corner_vertices = counts.corners;
      result.noise_crease_vertices = counts.noise_creases;
      result.boundary_vertices = counts.boundary;
      result.unfitted_vertices = counts.unfitted;
      result.not_moved_vertices = counts.not_moved;
      result.noise_level = counts.noise;
      if (params.progress) params.progress(static_cast<double>(i + 1) / static_cast<double>(params.iterations));
    }
  }
  result.iterations = params.iterations;
  if (keep_volume) {
    // The offset moves every vertex after the guard saw them: guard it too (the volume is then
    // kept up to the few vertices put back).
    const std::vector<TriMesh::Point> unrestored(mesh.points(), mesh.points() + mesh.n_vertices());
    restore_volume(mesh, *result.volume_before);
    if (params.method == SmoothMethod::Rbf) {
      moved_vertices += count_moved(mesh, unrestored);
      result.undone_vertices += detail::undo_new_intersections(mesh, unrestored, input_intersections);
    }
  }
  if (result.undone_vertices > 0)
    result.taken_back.push_back({"smooth", "self-intersection", "vertex moves", result.undone_vertices,
                                 "they made the surface cross itself beyond the input's " +
                                     std::to_string(input_intersections()) +
                                     " face pairs; those vertices stayed where the step found them",
                                 {{"vertex_moves", static_cast<double>(moved_vertices)}},
                                 {{"vertex_moves", static_cast<double>(moved_vertices - result.undone_vertices)}}});
  if (result.volume_before) result.volume_after = volume(mesh);
  for (const auto v : mesh.vertices())
    result.max_displacement =
        std::max(result.max_displacement, static_cast<double>((mesh.point(v) - before[static_cast<std::size_t>(v.idx())]).norm()));
  require_finite_points(mesh, "smooth");
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace meshprep
