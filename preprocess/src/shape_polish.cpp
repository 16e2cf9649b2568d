#include "shape_polish.h"

#include "triangle_angles.h"

#include "meshprep/preprocess/local_frame.h"

#include <algorithm>
#include <cmath>

namespace meshprep::detail {
namespace {

using VertexHandle = TriMesh::VertexHandle;

const double kFlatCosine = std::cos(10.0 * M_PI / 180.0);  // "nearly flat": dihedral under 10 degrees
const double kTurnCosine = std::cos(60.0 * M_PI / 180.0);  // largest normal turn of a relaxation move
constexpr double kFeatureVariation = 0.015;

Vec3 point(const TriMesh& mesh, VertexHandle v) { return to_eigen(mesh.point(v)); }

bool nearly_parallel(const Vec3& n0, const Vec3& n1) { return n0.dot(n1) >= kFlatCosine * n0.norm() * n1.norm(); }

std::size_t flip_sweep(TriMesh& mesh, double tolerance) {
  std::size_t flips = 0;
  for (const auto e : mesh.edges()) {
    if (mesh.status(e).deleted() || mesh.is_boundary(e) || !mesh.is_flip_ok(e)) continue;
    const auto h0 = mesh.halfedge_handle(e, 0), h1 = mesh.halfedge_handle(e, 1);
    const VertexHandle va = mesh.from_vertex_handle(h0), vb = mesh.to_vertex_handle(h0);
    if (mesh.valence(va) <= 3 || mesh.valence(vb) <= 3) continue;  // would leave a valence-2 vertex
    const Vec3 a = point(mesh, va), b = point(mesh, vb);
    const Vec3 c = point(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h0)));
    const Vec3 d = point(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h1)));
    const Vec3 n0 = area_normal(a, b, c), n1 = area_normal(b, a, d);
    const Vec3 m0 = area_normal(a, d, c), m1 = area_normal(d, b, c);  // the faces after the flip
    if (!nearly_parallel(n0, n1) || !nearly_parallel(m0, m1)) continue;
    const Vec3 normal = n0 + n1;
    if (m0.dot(normal) <= 0 || m1.dot(normal) <= 0) continue;
    if (std::abs((0.5 * (a + b) - 0.5 * (c + d)).dot(normal.normalized())) > tolerance) continue;
    const double before = std::max(smallest_angle_cosine(a, b, c), smallest_angle_cosine(b, a, d));
    const double after = std::max(smallest_angle_cosine(a, d, c), smallest_angle_cosine(d, b, c));
    if (after < before - 1e-12) {
      mesh.flip(e);
      ++flips;
    }
  }
  return flips;
}

// A vertex on a sharp edge or a corner stays put: a tangential move would round the feature off.
// The test is the paper's surface variation sigma = lambda1 / (lambda1 + lambda2 + lambda3) of the
// vertex and its 1-ring (local_frame.h). Its 0.3 never fires on a 1-ring (a 90-degree crease gives
// sigma ~0.13), so the threshold is sigma of a 30-degree crease, ~0.015: creases, corners and
// strongly curved tips are kept.
bool on_feature(const TriMesh& mesh, VertexHandle v, std::vector<Vec3>& ring) {
  ring.assign(1, point(mesh, v));
  for (const VertexHandle w : mesh.vv_range(v)) ring.push_back(point(mesh, w));
  return pca_frame(ring).surface_variation() > kFeatureVariation;
}

// Minimise Q(x + t n) over t (a parabola), |t| <= limit.
Vec3 slide_to_quadric(const Quadric& q, const Vec3& x, const Vec3& n, double limit) {
  const double f0 = evaluate(q, x), fp = evaluate(q, x + limit * n), fm = evaluate(q, x - limit * n);
  const double curvature = fp - 2 * f0 + fm;
  if (!(curvature > 0)) return x;
  const double t = std::clamp(-0.5 * limit * (fp - fm) / curvature, -limit, limit);
  return x + t * n;
}

std::size_t relax_sweep(TriMesh& mesh, const std::vector<Quadric>& quadrics, double tolerance) {
  std::size_t moves = 0;
  std::vector<Vec3> ring;
  for (const VertexHandle v : mesh.vertices()) {
    if (mesh.status(v).deleted() || mesh.is_boundary(v) || !mesh.is_manifold(v) || mesh.valence(v) < 3) continue;
    const Vec3 x = point(mesh, v);
    Vec3 centroid = Vec3::Zero(), normal = Vec3::Zero();
    double reach = 0;
    for (const VertexHandle w : mesh.vv_range(v)) {
      centroid += point(mesh, w);
      reach = std::max(reach, (point(mesh, w) - x).norm());
    }
    centroid /= static_cast<double>(mesh.valence(v));
    for (const auto f : mesh.vf_range(v)) {
      auto h = mesh.halfedge_handle(f);
      normal += area_normal(point(mesh, mesh.from_vertex_handle(h)), point(mesh, mesh.to_vertex_handle(h)),
                            point(mesh, mesh.to_vertex_handle(mesh.next_halfedge_handle(h))));
    }
    if (!(normal.norm() > 0)) continue;
    normal.normalize();
    const Vec3 tangential = centroid - normal * normal.dot(centroid - x);
    const Quadric& q = quadrics[static_cast<std::size_t>(v.idx())];
    const Vec3 y = slide_to_quadric(q, tangential, normal, 0.5 * reach);
    const double error = rms_plane_distance(q, y);
    if (error > tolerance && error > rms_plane_distance(q, x)) continue;
    const VertexMove move = vertex_move(mesh, v, y, kTurnCosine);
    if (move.turns || !(move.new_cosine < move.old_cosine)) continue;
    // Last, as the dearest test (a PCA with an eigen-solve): most vertices fail one of the above.
    if (on_feature(mesh, v, ring)) continue;
    mesh.set_point(v, to_openmesh(y));
    ++moves;
  }
  return moves;
}

}  // namespace

PolishCounts polish_shape(TriMesh& mesh, const std::vector<Quadric>& quadrics, double tolerance, bool flips) {
  PolishCounts counts;
  if (flips) counts.flips = flip_sweep(mesh, tolerance);
  counts.moves = relax_sweep(mesh, quadrics, tolerance);
  return counts;
}

}  // namespace meshprep::detail
