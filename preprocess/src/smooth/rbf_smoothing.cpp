#include "smooth/rbf_smoothing.h"

#include "smooth/filtered_normals.h"
#include "smooth/noise_adaptive.h"
#include "smooth/smoothing_neighbourhoods.h"
#include "shared/spatial_order.h"

#include "meshprep/core/errors.h"
#include "meshprep/preprocess/rbf/local_height_map.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <optional>

namespace meshprep {
namespace {

using detail::FeatureMap;
using detail::VertexGraph;

// How a neighbourhood's sites are weighted: a Gaussian of the distance to the vertex, sigma =
// kBandwidth x the vertex's mean edge. Measured on the noisy bunny and fandisk (docs/smoothing.md):
// 4 rings (kSmoothingRings) with sigma 2.5 edges beat 3 rings (truncating the Gaussian at 3 edges
// leaves noise) and 5 rings or any Euclidean cut-off (sites from around a bend).
constexpr double kBandwidth = 2.5;
// Fewest sites for the cubic height map (10 terms), with some margin against sites near one cubic curve.
constexpr std::size_t kFewestSites = 14;
// A crease is kept only where one surface over both of its sides fits them worse than this many
// times the median fit of the vertices on no crease (measured: at 1.5 about 100 noise-crease
// vertices of the noisy bunny stay, at 3 fandisk loses 45 of its real crease vertices).
constexpr double kCreaseResidual = 2.0;
// The narrow fit beside the wide one (noise_adaptive.h): the nearest sites, about 2 rings, and a
// Gaussian of this many edges. On coarse meshes it follows what 4 rings round off, and its moves
// measure the noise. Measured on the 23 closed meshes (docs/smoothing.md): 24 sites / 1.25 edges.
constexpr std::size_t kNarrowSites = 24;
constexpr double kNarrowBandwidth = 1.25;

Vec3 point(const TriMesh& mesh, TriMesh::VertexHandle v) { return to_eigen(mesh.point(v)); }

// The local surface of vertex p: the tangent-frame height map (local_height_map.h) of p and its
// neighbours, a cubic weighted by a Gaussian of the distance to p, and its weighted RMS residual
// (how well one smooth surface explains the sites: the noise, or a crease it cannot follow).
struct LocalSurface {
  LocalHeightMap map;
  double residual = 0;
  detail::FitWeights weights;  // of the fitted height at p (noise_adaptive.h)
};

LocalSurface fit_local_surface(const Vec3& p, std::vector<Vec3> sites, double mean_edge, double smoothing,
                               double bandwidth = kBandwidth) {
  sites.push_back(p);
  const double inverse_variance = 1 / std::pow(bandwidth * mean_edge, 2);
  Eigen::VectorXd weights(static_cast<Eigen::Index>(sites.size()));
  for (std::size_t j = 0; j < sites.size(); ++j)
    weights[static_cast<Eigen::Index>(j)] = std::exp(-0.5 * (sites[j] - p).squaredNorm() * inverse_variance);
  LocalSurface surface{LocalHeightMap(sites, HeightMapPolynomial::cubic, smoothing, weights), 0, {}};
  double weighted = 0;
  for (std::size_t j = 0; j < sites.size(); ++j) {
    const Vec3 local = surface.map.frame().to_local(sites[j]);
    weighted += weights[static_cast<Eigen::Index>(j)] * std::pow(local.z() - surface.map.spline().evaluate(local.x(), local.y()), 2);
  }
  surface.residual = std::sqrt(weighted / weights.sum());
  // The fitted height at p is linear in the sites' heights, sum_j a_j z_j (weighted least squares):
  // a_j = w_j x_j^T (X^T W X)^-1 x_p. Its own coefficient (the last site is p) and sum of squares
  // give the share of p's noise the fit keeps and the variance of its value.
  const Vec3 centre = surface.map.frame().to_local(p);
  const double scale = 1 / mean_edge;
  auto basis = [&](const Vec3& q) {
    const double x = (q.x() - centre.x()) * scale, y = (q.y() - centre.y()) * scale;
    Eigen::Matrix<double, 10, 1> b;
    b << 1, x, y, x * x, x * y, y * y, x * x * x, x * x * y, x * y * y, y * y * y;
    return b;
  };
  Eigen::Matrix<double, 10, 10> normal = Eigen::Matrix<double, 10, 10>::Zero();
  std::vector<Eigen::Matrix<double, 10, 1>> rows(sites.size());
  for (std::size_t j = 0; j < sites.size(); ++j) {
    rows[j] = basis(surface.map.frame().to_local(sites[j]));
    normal.noalias() += weights[static_cast<Eigen::Index>(j)] * rows[j] * rows[j].transpose();
  }
  Eigen::Matrix<double, 10, 1> at_p = Eigen::Matrix<double, 10, 1>::Zero();
  at_p[0] = 1;
  const Eigen::Matrix<double, 10, 1> c = normal.ldlt().solve(at_p);
  double sum2 = 0, own = 0;
  for (std::size_t j = 0; j < sites.size(); ++j) {
    const double a = weights[static_cast<Eigen::Index>(j)] * rows[j].dot(c);
    sum2 += a * a;
    if (j + 1 == sites.size()) own = a;
  }
  surface.weights = {own, sum2};
  return surface;
}

// What one vertex needs from its 1-ring.
struct Ring {
  Vec3 centroid = Vec3::Zero();
  double mean_edge = 0;
};

Ring ring_of(const TriMesh& mesh, TriMesh::VertexHandle v) {
  Ring ring;
  const Vec3 p = point(mesh, v);
  int valence = 0;
  for (const auto u : mesh.vv_range(v)) {
    const Vec3 q = point(mesh, u);
    ring.centroid += q;
    ring.mean_edge += (q - p).norm();
    ++valence;
  }
  ring.centroid /= valence;
  ring.mean_edge /= valence;
  return ring;
}

// A surface vertex's new place: its point relaxed towards the centroid of its 1-ring (the
// tangential part of that move evens out the triangles), moved onto its local surface.
Vec3 onto_surface(const LocalSurface& surface, const Vec3& p, const Ring& ring, double relaxation) {
  return surface.map.project(p + relaxation * (ring.centroid - p));
}

}  // namespace

std::vector<Vec3> rbf_smoothing_step(const TriMesh& mesh, const SmoothParams& params, RbfIterationCounts& counts) {
  const std::vector<Vec3> normals = detail::filtered_face_normals(mesh);
  const double cos_limit = std::cos(params.feature_angle_deg * M_PI / 180);
  const FeatureMap features{normals, detail::crease_edges(mesh, normals, cos_limit), cos_limit};
  const std::size_t n = mesh.n_vertices();
  std::vector<Vec3> moved(n);
  std::vector<std::size_t> creases(n, 0);
  constexpr double kUnfitted = -1;
  std::vector<double> residual(n, kUnfitted);
  double noise = 0;
  std::size_t not_moved = 0;
  std::atomic<std::size_t> feature_line{0}, corners{0}, boundary{0}, unfitted{0}, noise_creases{0};
  const VertexGraph graph = detail::vertex_graph(mesh, features);
  // Where the wide (params.neighbors, kBandwidth) and the narrow fits put each vertex.
  std::array<detail::MoveProposal, 2> proposals{detail::MoveProposal(n), detail::MoveProposal(n)};
  auto propose = [&](std::size_t i, const Vec3& target, const LocalSurface& surface, const Vec3& p, int which) {
    proposals[static_cast<std::size_t>(which)].set(i, target, (surface.map.project(p) - p).dot(graph.normal[i]), surface.weights);
  };
  // The local surface of vertex i through `neighbours` (v excluded), if they hold one.
  auto fitted = [&](std::size_t i, std::vector<Vec3> neighbours, const Ring& ring,
                    double bandwidth = kBandwidth) -> std::optional<LocalSurface> {
    const TriMesh::VertexHandle v(static_cast<int>(i));
    if (neighbours.size() + 1 < kFewestSites) return std::nullopt;
    try {
      return fit_local_surface(point(mesh, v), std::move(neighbours), ring.mean_edge, params.smoothing, bandwidth);
    } catch (const InvalidInput&) {  // sites on one cubic curve, or coinciding: no surface
      return std::nullopt;
    }
  };
  // A move longer than the vertex's mean edge is refused: a local surface that is not a graph over
  // its frame (a thin part folded into the neighbourhood) can throw the vertex far, and the
  // alternating projections onto a feature line's two sides can diverge (the corpus's handle and
  // spool, at edges of their holes): a NaN target is refused as well.
  auto place = [&](std::size_t i, const Vec3& target, const Ring& ring) {
    if (!((target - moved[i]).norm() <= ring.mean_edge)) {
      ++unfitted;
      return false;
    }
    moved[i] = target;
    return true;
  };

  // The vertices in Morton order: a vertex's neighbourhood then overlaps the previous one's, in
  // the cache (the file's order can be anything: the noisy bunny's is random).
  std::vector<Vec3> positions(n);
  for (std::size_t i = 0; i < n; ++i) positions[i] = point(mesh, TriMesh::VertexHandle(static_cast<int>(i)));
  const std::vector<std::uint32_t> order = detail::morton_order(positions);

  // 1. Vertices on no crease, each onto the surface of its neighbours on its side of any feature.
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t k) {
    const std::size_t i = order[k];
    const TriMesh::VertexHandle v(static_cast<int>(i));
    moved[i] = point(mesh, v);
    if (mesh.status(v).deleted() || mesh.is_isolated(v)) return;
    if (mesh.is_boundary(v)) {
      ++boundary;
      return;
    }
    for (const auto e : mesh.ve_range(v)) creases[i] += features.crease[static_cast<std::size_t>(e.idx())];
    if (creases[i] > 0) return;
    const Ring ring = ring_of(mesh, v);
    std::vector<Vec3> sites = detail::nearby_vertices(mesh, graph, static_cast<std::uint32_t>(i), cos_limit, false, params.neighbors);
    const std::optional<LocalSurface> surface = fitted(i, sites, ring);
    if (!surface) {
      ++unfitted;
      return;
    }
    const Vec3 p = point(mesh, v);
    if (place(i, onto_surface(*surface, moved[i], ring, params.relaxation), ring)) {
      residual[i] = surface->residual;
      if (!params.adaptive) return;
      propose(i, moved[i], *surface, p, 0);
      propose(i, moved[i], *surface, p, 1);  // unless a narrow fit is found
      // The narrow fit: the kNarrowSites nearest sites, a Gaussian of kNarrowBandwidth edges.
      if (sites.size() > kNarrowSites) {
        std::nth_element(sites.begin(), sites.begin() + static_cast<std::ptrdiff_t>(kNarrowSites), sites.end(),
                         [&](const Vec3& a, const Vec3& b) { return (a - p).squaredNorm() < (b - p).squaredNorm(); });
        sites.resize(kNarrowSites);
      }
      const std::optional<LocalSurface> narrow = fitted(i, sites, ring, kNarrowBandwidth);
      if (!narrow) return;
      const Vec3 target = onto_surface(*narrow, p, ring, params.relaxation);
      if ((target - p).norm() <= ring.mean_edge) propose(i, target, *narrow, p, 1);
    }
  });

  // 2. What one surface leaves unexplained where there is no crease: the noise level.
  std::vector<double> surface_residuals;
  for (const double r : residual)
    if (r != kUnfitted) surface_residuals.push_back(r);
  double noise_level = 0;  // no vertex off the creases: every crease is trusted
  if (!surface_residuals.empty()) {
    const auto middle = surface_residuals.begin() + static_cast<std::ptrdiff_t>(surface_residuals.size() / 2);
    std::nth_element(surface_residuals.begin(), middle, surface_residuals.end());
    noise_level = *middle;
  }

  // 3. Vertices on creases. Noise makes creases too (a scan's filtered normals still turn by 45
  // degrees at places): where one surface over both sides fits about as well as elsewhere, the
  // crease is noise and the vertex is smoothed as a surface vertex. Otherwise a vertex on exactly
  // two creases lies on a feature line and is projected, in turn, onto the surfaces of its two
  // sides, which converges to their intersection, so the edge stays sharp; a vertex on one crease,
  // or three or more, is a corner and stays.
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t k) {
    const std::size_t i = order[k];
    if (creases[i] == 0) return;  // done above (boundary vertices have no crease: they stay)
    const TriMesh::VertexHandle v(static_cast<int>(i));
    const Ring ring = ring_of(mesh, v);
    const std::optional<LocalSurface> across =
        fitted(i, detail::nearby_vertices(mesh, graph, static_cast<std::uint32_t>(i), -1.0, true, params.neighbors), ring);
    if (across && across->residual < kCreaseResidual * noise_level) {
      ++noise_creases;
      if (place(i, onto_surface(*across, moved[i], ring, params.relaxation), ring))
        for (int which = 0; which < 2; ++which) propose(i, moved[i], *across, point(mesh, v), which);
      return;
    }
    if (creases[i] != 2) {
      ++corners;
      return;
    }
    const auto fans = detail::fans_between_creases(mesh, v, features.crease);
    auto side = [&](const std::vector<TriMesh::FaceHandle>& fan) {
      return fitted(i, detail::same_side_neighbours(mesh, v, fan, features, params.neighbors), ring);
    };
    const std::optional<LocalSurface> first = side(fans[0]), second = side(fans[1]);
    if (!first || !second) {
      ++unfitted;
      return;
    }
    Vec3 x = moved[i];
    for (int round = 0; round < 4; ++round) x = second->map.project(first->map.project(x));
    if (place(i, x, ring)) {
      ++feature_line;
      // Both sides' fits moved it: its own move is the whole move, its weights the first side's.
      for (std::size_t which = 0; which < 2; ++which)
        proposals[which].set(i, x, (x - point(mesh, v)).dot(graph.normal[i]), first->weights);
    }
  });
  if (params.adaptive) {
    // 4. How much of which fit each vertex takes, from the noise the mesh shows.
    std::vector<Vec3> points(n);
    for (std::size_t i = 0; i < n; ++i) points[i] = point(mesh, TriMesh::VertexHandle(static_cast<int>(i)));
    const detail::NoiseAdaptiveCounts adapted = detail::choose_moves(points, graph, proposals, moved);
    noise = adapted.noise;
    not_moved = adapted.not_moved;
  }
  counts = {feature_line, corners, boundary, unfitted, noise_creases, not_moved, noise};
  return moved;
}

}  // namespace meshprep
