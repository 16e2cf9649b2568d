#include "shared/surface_fit.h"

#include "shared/triangle_angles.h"
#include "shared/vertex_relaxation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace meshprep::detail {
namespace {

using VertexHandle = TriMesh::VertexHandle;

const double kTurnCosine = std::cos(30.0 * M_PI / 180.0);
constexpr double kStepCap = 0.25;  // of the shortest edge at the vertex

Vec3 point(const TriMesh& mesh, VertexHandle v) { return to_eigen(mesh.point(v)); }

// Sums of the least-squares step along the normal: t = -sum w n.r / sum w^2.
struct NormalStep {
  Vec3 weighted_residual = Vec3::Zero();  // sum w (p - c)
  double weight_squares = 0;              // sum w^2
  void add(const TriangleBvh& reference, const Vec3& p, double weight) {
    weighted_residual += weight * (p - reference.closest_point(p).point);
    weight_squares += weight * weight;
  }
};

// The move keeps every face within 30 degrees of its normal and does not take a smallest angle
// below min(the guard's bound, what it was).
bool move_keeps_shape(const TriMesh& mesh, VertexHandle v, const Vec3& moved_to, double min_angle_cosine,
                      const HeightField& field) {
  const VertexMove move = vertex_move(mesh, v, moved_to, kTurnCosine, field);
  return !move.turns && move.new_cosine <= std::max(min_angle_cosine, move.old_cosine);
}

}  // namespace

std::size_t fit_to_reference(TriMesh& mesh, const TriangleBvh& reference, double min_angle_cosine,
                             const HeightField& field, const std::vector<char>* movable) {
  std::size_t moved = 0;
  const FacePatches patches(mesh);
  for (const VertexHandle v : mesh.vertices()) {
    if (!relaxable(mesh, v, patches)) continue;
    if (movable && !(*movable)[static_cast<std::size_t>(v.idx())]) continue;
    const Vec3 x = point(mesh, v);
    double shortest = std::numeric_limits<double>::infinity();
    for (const VertexHandle w : mesh.vv_range(v)) shortest = std::min(shortest, (point(mesh, w) - x).norm());
    Vec3 normal = Vec3::Zero();
    NormalStep step;
    step.add(reference, x, 1.0);
    for (const auto f : mesh.vf_range(v)) {
      Vec3 corners[3];
      int k = 0, own = 0;
      for (const VertexHandle w : mesh.fv_range(f)) {
        if (w == v) own = k;
        corners[k++] = point(mesh, w);
      }
      normal += area_normal(corners[0], corners[1], corners[2]);
      const Vec3 others = corners[(own + 1) % 3] + corners[(own + 2) % 3];
      step.add(reference, (x + others) / 3.0, 1.0 / 3.0);
      step.add(reference, (4.0 * x + others) / 6.0, 2.0 / 3.0);
    }
    if (!(normal.norm() > 0)) continue;
    normal.normalize();
    const double limit = kStepCap * shortest;
    const double t = std::clamp(-normal.dot(step.weighted_residual) / step.weight_squares, -limit, limit);
    const Vec3 y = x + t * normal;
    if (t == 0 || !move_keeps_shape(mesh, v, y, min_angle_cosine, field)) continue;
    mesh.set_point(v, to_openmesh(y));
    ++moved;
  }
  return moved;
}

}  // namespace meshprep::detail
