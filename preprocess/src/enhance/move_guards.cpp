#include "enhance/move_guards.h"

#include "shared/intersection_guard.h"
#include "shared/triangle_angles.h"

#include <tbb/parallel_for.h>

#include <array>
#include <cmath>

namespace meshprep::detail {
namespace {

const double kTurnCosine = std::cos(60.0 * M_PI / 180.0);  // largest normal turn of a face in one round

using Corners = std::array<Vec3, 3>;

Corners corners_of(const TriMesh& mesh, TriMesh::FaceHandle f, const std::vector<TriMesh::Point>* at = nullptr) {
  Corners p;
  std::size_t k = 0;
  for (const auto v : mesh.fv_range(f)) p[k++] = to_eigen(at ? (*at)[static_cast<std::size_t>(v.idx())] : mesh.point(v));
  return p;
}

Vec3 normal_of(const Corners& p) { return (p[1] - p[0]).cross(p[2] - p[0]); }

// How far a face is from the reference: the largest distance of its centroid and edge midpoints
// (its corners are on the reference).
double face_deviation(const Corners& p, const SurfaceConstraints& constraints) {
  double worst = 0;
  for (const Vec3& q : {Vec3((p[0] + p[1] + p[2]) / 3.0), Vec3(0.5 * (p[0] + p[1])), Vec3(0.5 * (p[1] + p[2])), Vec3(0.5 * (p[2] + p[0]))})
    worst = std::max(worst, constraints.closest_on_reference(q).squared_distance);
  return std::sqrt(worst);
}

bool touches(const TriMesh& mesh, std::size_t face, const std::vector<char>& dirty) {
  for (const auto v : mesh.fv_range(TriMesh::FaceHandle(static_cast<int>(face))))
    if (dirty[static_cast<std::size_t>(v.idx())]) return true;
  return false;
}

}  // namespace

std::vector<TriangleBvh::Hit> reference_coverage(const TriMesh& mesh, const std::vector<Vec3>& probes) {
  const MeshSoupView surface(mesh);
  const TriangleBvh bvh(surface);
  std::vector<TriangleBvh::Hit> hits(probes.size());
  tbb::parallel_for(std::size_t(0), hits.size(), [&](std::size_t i) { hits[i] = bvh.closest_point(probes[i]); });
  return hits;
}

MoveGuards::MoveGuards(const TriMesh& mesh, const SurfaceConstraints& constraints, const std::vector<Vec3>& probes,
                       const std::vector<double>& allowed_distance, std::size_t allowed_intersections, double max_deviation)
    : constraints_(constraints),
      probes_(probes),
      allowed_distance_(allowed_distance),
      allowed_intersections_(allowed_intersections),
      max_deviation_(max_deviation),
      before_(mesh.points(), mesh.points() + mesh.n_vertices()),
      coverage_before_(reference_coverage(mesh, probes)) {}

bool MoveGuards::moved(const TriMesh& mesh, TriMesh::VertexHandle v) const {
  return mesh.point(v) != before_[static_cast<std::size_t>(v.idx())];
}

std::size_t MoveGuards::put_back(TriMesh& mesh, TriMesh::FaceHandle f) const {
  std::size_t undone = 0;
  for (const auto v : mesh.fv_range(f))
    if (moved(mesh, v)) {
      mesh.set_point(v, before_[static_cast<std::size_t>(v.idx())]);
      ++undone;
    }
  return undone;
}

UndoneMoves& UndoneMoves::operator+=(const UndoneMoves& other) {
  moved += other.moved;
  bad_faces += other.bad_faces;
  uncovering += other.uncovering;
  intersections += other.intersections;
  return *this;
}

UndoneMoves MoveGuards::enforce(TriMesh& mesh) const {
  UndoneMoves undone;
  std::vector<char> dirty(mesh.n_vertices(), 0);  // vertices whose position changed since the last look
  for (const auto v : mesh.vertices()) {
    dirty[static_cast<std::size_t>(v.idx())] = moved(mesh, v);
    undone.moved += moved(mesh, v);
  }
  std::vector<std::size_t> nearest_face(coverage_before_.size());
  for (std::size_t i = 0; i < nearest_face.size(); ++i) nearest_face[i] = coverage_before_[i].face;
  for (int pass = 0; pass < 8; ++pass) {
    const std::vector<TriMesh::Point> start(mesh.points(), mesh.points() + mesh.n_vertices());
    undone.bad_faces += undo_bad_faces(mesh, dirty);
    undone.uncovering += undo_uncovering(mesh, dirty, nearest_face);
    undone.intersections += undo_new_intersections(mesh, before_, allowed_intersections_);
    bool changed = false;
    for (const auto v : mesh.vertices()) {
      const std::size_t i = static_cast<std::size_t>(v.idx());
      dirty[i] = mesh.point(v) != start[i];
      changed = changed || dirty[i];
    }
    if (!changed) break;
  }
  return undone;
}

// Faces that turned by more than 60 degrees, and faces carried farther from the reference than the
// bound (and than they were): their moved vertices go back, and the faces around those are looked
// at again, until none is left. Each sweep measures its faces in parallel.
std::size_t MoveGuards::undo_bad_faces(TriMesh& mesh, const std::vector<char>& dirty) const {
  std::vector<TriMesh::FaceHandle> suspects;
  for (const auto f : mesh.faces())
    if (touches(mesh, static_cast<std::size_t>(f.idx()), dirty)) suspects.push_back(f);
  std::size_t undone = 0;
  std::vector<char> queued(mesh.n_faces(), 0);
  while (!suspects.empty()) {
    std::vector<char> bad(suspects.size(), 0);
    tbb::parallel_for(std::size_t(0), suspects.size(), [&](std::size_t k) {
      const Corners old_corners = corners_of(mesh, suspects[k], &before_), corners = corners_of(mesh, suspects[k]);
      const Vec3 n0 = normal_of(old_corners), n1 = normal_of(corners);
      if (n0.dot(n1) <= kTurnCosine * n0.norm() * n1.norm()) {
        bad[k] = 1;
        return;
      }
      for (const auto h : mesh.fh_range(suspects[k])) {  // no new fold with a neighbour (its move included)
        const auto g = mesh.opposite_face_handle(h);
        if (!g.is_valid()) continue;
        const Vec3 m0 = normal_of(corners_of(mesh, g, &before_)), m1 = normal_of(corners_of(mesh, g));
        if (sharpens_into_fold(normal_cosine(n0, m0), normal_cosine(n1, m1))) {
          bad[k] = 1;
          return;
        }
      }
      const double deviation = face_deviation(corners, constraints_);
      bad[k] = deviation > max_deviation_ && deviation > face_deviation(old_corners, constraints_);
    });
    std::vector<TriMesh::VertexHandle> reverted;
    for (std::size_t k = 0; k < suspects.size(); ++k) {
      queued[static_cast<std::size_t>(suspects[k].idx())] = 0;
      if (!bad[k]) continue;
      for (const auto v : mesh.fv_range(suspects[k]))
        if (moved(mesh, v)) reverted.push_back(v);
      undone += put_back(mesh, suspects[k]);
    }
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

// A probe of the reference the mesh has moved away from sends the vertices of its nearest faces, now and
// at the start of the round, back. Its distance can only have grown if the face it was nearest to
// at the last look has changed since, so only those are measured again.
std::size_t MoveGuards::undo_uncovering(TriMesh& mesh, const std::vector<char>& dirty, std::vector<std::size_t>& nearest_face) const {
  std::vector<std::size_t> suspects;
  for (std::size_t i = 0; i < nearest_face.size(); ++i)
    if (touches(mesh, nearest_face[i], dirty)) suspects.push_back(i);
  if (suspects.empty()) return 0;
  const MeshSoupView surface(mesh);
  const TriangleBvh bvh(surface);
  std::vector<TriangleBvh::Hit> coverage(suspects.size());
  tbb::parallel_for(std::size_t(0), suspects.size(), [&](std::size_t k) { coverage[k] = bvh.closest_point(probes_[suspects[k]]); });
  std::size_t undone = 0;
  for (std::size_t k = 0; k < suspects.size(); ++k) {
    const std::size_t i = suspects[k];
    nearest_face[i] = coverage[k].face;
    if (coverage[k].squared_distance <= allowed_distance_[i] * allowed_distance_[i]) continue;
    for (const std::size_t face : {coverage[k].face, coverage_before_[i].face}) undone += put_back(mesh, TriMesh::FaceHandle(static_cast<int>(face)));
  }
  return undone;
}

}  // namespace meshprep::detail
