#include "rbf_smoothing.h"

#include "spatial_order.h"

#include "meshprep/core/errors.h"
#include "meshprep/preprocess/local_height_map.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <optional>

namespace meshprep {
namespace {

// How far a neighbourhood reaches (in edges) and how its sites are weighted: a Gaussian of the
// distance to the vertex, sigma = kBandwidth x the vertex's mean edge. Measured on the noisy bunny
// and fandisk (docs/smoothing.md): 4 rings with sigma 2.5 edges beat 3 rings (truncating the
// Gaussian at 3 edges leaves noise) and 5 rings or any Euclidean cut-off (sites from around a bend).
constexpr int kRings = 4;
constexpr double kBandwidth = 2.5;
// Fewest sites for the cubic height map (10 terms), with some margin against sites near one cubic curve.
constexpr std::size_t kFewestSites = 14;
// A crease is kept only where one surface over both of its sides fits them worse than this many
// times the median fit of the vertices on no crease (measured: at 1.5 about 100 noise-crease
// vertices of the noisy bunny stay, at 3 fandisk loses 45 of its real crease vertices).
constexpr double kCreaseResidual = 2.0;

Vec3 point(const TriMesh& mesh, TriMesh::VertexHandle v) { return to_eigen(mesh.point(v)); }

// Face normals denoised by bilateral filtering (Zheng, Fu, Au and Tai 2011): each normal becomes
// the mean of the normals of the faces around it (sharing a vertex), weighted by area, by a
// Gaussian of the centroid distance (sigma: the mean edge length) and by a Gaussian of the normal
// difference (sigma 0.35, about 20 degrees), so that noise averages out while the normals on the
// two sides of a crease do not mix. Creases are then found on these normals: noise alone (a
// scanned surface's small triangles tilt by tens of degrees) does not make a crease.
std::vector<Vec3> filtered_face_normals(const TriMesh& mesh) {
  const std::size_t n = mesh.n_faces();
  std::vector<Vec3> normals(n), centroids(n);
  std::vector<double> areas(n);
  double edge_sum = 0;
  for (const auto e : mesh.edges()) edge_sum += mesh.calc_edge_length(e);
  const double sigma_centre = edge_sum / static_cast<double>(std::max<std::size_t>(mesh.n_edges(), 1));
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    auto corner = mesh.cfv_begin(TriMesh::FaceHandle(static_cast<int>(i)));
    const Vec3 a = point(mesh, *corner), b = point(mesh, *++corner), c = point(mesh, *++corner);
    const Vec3 cross = (b - a).cross(c - a);
    areas[i] = 0.5 * cross.norm();
    normals[i] = areas[i] > 0 ? Vec3(cross.normalized()) : Vec3::Zero();
    centroids[i] = (a + b + c) / 3;
  });
  // The faces around each face (sharing a vertex), in compressed rows, each with its spatial
  // weight (area x the centroid Gaussian), which no round changes. Gathered from the faces of each
  // vertex (compressed rows too) and each face's corners: plain arrays, not circulators.
  std::vector<std::size_t> vertex_first(mesh.n_vertices() + 1, 0);
  for (const auto f : mesh.faces())
    for (const auto v : mesh.fv_range(f)) ++vertex_first[static_cast<std::size_t>(v.idx()) + 1];
  for (std::size_t v = 0; v < mesh.n_vertices(); ++v) vertex_first[v + 1] += vertex_first[v];
  std::vector<int> vertex_faces(vertex_first.back());
  std::vector<std::array<int, 3>> corners(n);
  {
    std::vector<std::size_t> filled(vertex_first.begin(), vertex_first.end() - 1);
    for (const auto f : mesh.faces()) {
      int k = 0;
      for (const auto v : mesh.fv_range(f)) {
        corners[static_cast<std::size_t>(f.idx())][k++] = v.idx();
        vertex_faces[filled[static_cast<std::size_t>(v.idx())]++] = f.idx();
      }
    }
  }
  auto around_face = [&](std::size_t i, std::vector<int>& faces) {
    faces.clear();
    for (const int v : corners[i])
      for (std::size_t k = vertex_first[static_cast<std::size_t>(v)]; k < vertex_first[static_cast<std::size_t>(v) + 1]; ++k)
        if (std::find(faces.begin(), faces.end(), vertex_faces[k]) == faces.end()) faces.push_back(vertex_faces[k]);
  };
  std::vector<std::size_t> first(n + 1, 0);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    thread_local std::vector<int> faces;
    around_face(i, faces);
    first[i + 1] = faces.size();
  });
  for (std::size_t i = 0; i < n; ++i) first[i + 1] += first[i];
  std::vector<int> around(first[n]);
  std::vector<double> spatial(first[n]);
  const double centre_scale = 0.5 / (sigma_centre * sigma_centre);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    thread_local std::vector<int> faces;
    around_face(i, faces);
    for (std::size_t k = 0; k < faces.size(); ++k) {
      const auto j = static_cast<std::size_t>(faces[k]);
      around[first[i] + k] = faces[k];
      spatial[first[i] + k] = areas[j] * std::exp(-centre_scale * (centroids[j] - centroids[i]).squaredNorm());
    }
  });
  constexpr double kSigmaNormal = 0.35;
  constexpr double kNormalScale = 0.5 / (kSigmaNormal * kSigmaNormal);
  constexpr int kIterations = 5;
  std::vector<Vec3> next(n);
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
      Vec3 sum = Vec3::Zero();
      for (std::size_t k = first[i]; k < first[i + 1]; ++k) {
        const Vec3& normal = normals[static_cast<std::size_t>(around[k])];
        sum += spatial[k] * std::exp(-kNormalScale * (normal - normals[i]).squaredNorm()) * normal;
      }
      next[i] = sum.norm() > 0 ? Vec3(sum.normalized()) : normals[i];
    });
    normals.swap(next);
  }
  return normals;
}

// The crease edges: interior edges whose faces' normals differ by more than the feature angle.
std::vector<char> crease_edges(const TriMesh& mesh, const std::vector<Vec3>& normals, double cos_limit) {
  std::vector<char> crease(mesh.n_edges(), 0);
  tbb::parallel_for(std::size_t(0), mesh.n_edges(), [&](std::size_t i) {
    const TriMesh::EdgeHandle e(static_cast<int>(i));
    if (mesh.is_boundary(e)) return;
    const auto f0 = mesh.face_handle(mesh.halfedge_handle(e, 0)), f1 = mesh.face_handle(mesh.halfedge_handle(e, 1));
    crease[i] = normals[static_cast<std::size_t>(f0.idx())].dot(normals[static_cast<std::size_t>(f1.idx())]) < cos_limit;
  });
  return crease;
}

// Where the neighbourhood of a vertex may reach: not across a crease, not to a face turned more
// than the feature angle from the side it starts on (a crease that fades out, or the far side of
// a corner, would otherwise be reached around the end of the crease line).
struct FeatureMap {
  const std::vector<Vec3>& normals;  // unit face normals
  std::vector<char> crease;          // per edge
  double cos_limit = -1;
};

// Membership marks for one neighbourhood search at a time per thread: an element is in the
// current set when its mark equals the current stamp (no clearing between vertices).
struct SearchMarks {
  std::vector<unsigned> in_rings, listed, in_region;  // per vertex, per vertex, per face
  unsigned stamp = 0;
  void next(const TriMesh& mesh) {
    in_rings.resize(mesh.n_vertices(), 0);
    listed.resize(mesh.n_vertices(), 0);
    in_region.resize(mesh.n_faces(), 0);
    if (++stamp == 0) {  // wrapped: clear once
      for (auto* marks : {&in_rings, &listed, &in_region}) std::fill(marks->begin(), marks->end(), 0);
      stamp = 1;
    }
  }
};

// The vertices of the faces reached from `seeds` across non-crease edges, among the faces whose
// corners are all within kRings rings of v and whose normals are within the feature angle of the
// seeds' mean normal: v's neighbourhood on one side of any feature. The N nearest to v (v
// excluded) are returned.
std::vector<Vec3> same_side_neighbours(const TriMesh& mesh, TriMesh::VertexHandle v,
                                       const std::vector<TriMesh::FaceHandle>& seeds, const FeatureMap& features,
                                       std::size_t count) {
  thread_local SearchMarks marks;
  marks.next(mesh);
  const unsigned stamp = marks.stamp;
  auto& in_rings = marks.in_rings;
  auto& in_region = marks.in_region;
  Vec3 side = Vec3::Zero();
  for (const auto f : seeds) side += features.normals[static_cast<std::size_t>(f.idx())];
  side.normalize();
  // v and its rings up to depth kRings.
  std::vector<TriMesh::VertexHandle> rings{v};
  in_rings[static_cast<std::size_t>(v.idx())] = stamp;
  std::size_t ring_begin = 0;
  for (int depth = 0; depth < kRings; ++depth) {
    const std::size_t ring_end = rings.size();
    for (std::size_t i = ring_begin; i < ring_end; ++i)
      for (const auto w : mesh.vv_range(rings[i]))
        if (in_rings[static_cast<std::size_t>(w.idx())] != stamp) {
          in_rings[static_cast<std::size_t>(w.idx())] = stamp;
          rings.push_back(w);
        }
    ring_begin = ring_end;
  }
  auto reachable = [&](TriMesh::FaceHandle f) {
    if (features.normals[static_cast<std::size_t>(f.idx())].dot(side) < features.cos_limit) return false;
    for (const auto c : mesh.fv_range(f))
      if (in_rings[static_cast<std::size_t>(c.idx())] != stamp) return false;
    return true;
  };
  std::vector<TriMesh::FaceHandle> region;
  for (const auto f : seeds)
    if (in_region[static_cast<std::size_t>(f.idx())] != stamp) {
      in_region[static_cast<std::size_t>(f.idx())] = stamp;
      region.push_back(f);
    }
  for (std::size_t i = 0; i < region.size(); ++i)
    for (const auto h : mesh.fh_range(region[i])) {
      if (features.crease[static_cast<std::size_t>(mesh.edge_handle(h).idx())]) continue;
      const auto g = mesh.opposite_face_handle(h);
      if (!g.is_valid() || in_region[static_cast<std::size_t>(g.idx())] == stamp || !reachable(g)) continue;
      in_region[static_cast<std::size_t>(g.idx())] = stamp;
      region.push_back(g);
    }
  // The region's vertices (v excluded), each once.
  std::vector<std::pair<double, int>> found;
  const Vec3 centre = point(mesh, v);
  marks.listed[static_cast<std::size_t>(v.idx())] = stamp;
  for (const auto f : region)
    for (const auto c : mesh.fv_range(f)) {
      unsigned& mark = marks.listed[static_cast<std::size_t>(c.idx())];
      if (mark == stamp) continue;
      mark = stamp;
      found.emplace_back((point(mesh, c) - centre).squaredNorm(), c.idx());
    }
  if (found.size() > count) {  // the `count` nearest, in no particular order (the fit does not care)
    std::nth_element(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(count), found.end());
    found.resize(count);
  }
  std::vector<Vec3> neighbours;
  neighbours.reserve(found.size() + 1);  // the caller adds the vertex itself
  for (const auto& [squared, index] : found) neighbours.push_back(point(mesh, TriMesh::VertexHandle(index)));
  return neighbours;
}

// The mesh's vertex graph in compressed rows, with the crease flag of each edge and the filtered
// normal of each vertex (the mean of its faces'): the neighbourhood search of the vertices on no
// crease walks it, several times faster than the face search above with OpenMesh's circulators.
struct VertexGraph {
  std::vector<std::uint32_t> first;  // row v is [first[v], first[v + 1])
  std::vector<std::uint32_t> neighbour;
  std::vector<char> crease;          // per entry of `neighbour`
  std::vector<Vec3> normal;          // per vertex
};

VertexGraph vertex_graph(const TriMesh& mesh, const FeatureMap& features) {
  const std::size_t n = mesh.n_vertices();
  VertexGraph graph;
  graph.first.assign(n + 1, 0);
  for (std::size_t v = 0; v < n; ++v)
    graph.first[v + 1] = graph.first[v] + static_cast<std::uint32_t>(mesh.valence(TriMesh::VertexHandle(static_cast<int>(v))));
  graph.neighbour.resize(graph.first[n]);
  graph.crease.resize(graph.first[n]);
  graph.normal.assign(n, Vec3::Zero());
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t v) {
    const TriMesh::VertexHandle handle(static_cast<int>(v));
    std::uint32_t k = graph.first[v];
    for (const auto h : mesh.voh_range(handle)) {
      graph.neighbour[k] = static_cast<std::uint32_t>(mesh.to_vertex_handle(h).idx());
      graph.crease[k++] = features.crease[static_cast<std::size_t>(mesh.edge_handle(h).idx())];
    }
    for (const auto f : mesh.vf_range(handle)) graph.normal[v] += features.normals[static_cast<std::size_t>(f.idx())];
    graph.normal[v].normalize();
  });
  return graph;
}

// The vertices within kRings edges of v, reached without walking along a crease (unless
// `across_creases`) and whose normals are within the feature angle of v's (cos_limit; -1 for
// any): v's neighbourhood on its side of any feature. The N nearest to v (v excluded).
std::vector<Vec3> nearby_vertices(const TriMesh& mesh, const VertexGraph& graph, std::uint32_t v, double cos_limit,
                                  bool across_creases, std::size_t count) {
  thread_local std::vector<unsigned> mark;
  thread_local unsigned stamp = 0;
  if (mark.size() != mesh.n_vertices()) {
    mark.assign(mesh.n_vertices(), 0);
    stamp = 0;
  }
  if (++stamp == 0) {  // wrapped: clear once
    std::fill(mark.begin(), mark.end(), 0);
    stamp = 1;
  }
  const Vec3 centre = point(mesh, TriMesh::VertexHandle(static_cast<int>(v)));
  const Vec3& side = graph.normal[v];
  thread_local std::vector<std::uint32_t> reached;
  thread_local std::vector<std::pair<double, std::uint32_t>> found;
  reached.assign(1, v);
  found.clear();
  mark[v] = stamp;
  std::size_t ring_begin = 0;
  for (int depth = 0; depth < kRings; ++depth) {
    const std::size_t ring_end = reached.size();
    for (std::size_t i = ring_begin; i < ring_end; ++i)
      for (std::uint32_t k = graph.first[reached[i]]; k < graph.first[reached[i] + 1]; ++k) {
        const std::uint32_t w = graph.neighbour[k];
        if (mark[w] == stamp || (graph.crease[k] && !across_creases)) continue;
        mark[w] = stamp;
        if (graph.normal[w].dot(side) < cos_limit) continue;
        reached.push_back(w);
        found.emplace_back((point(mesh, TriMesh::VertexHandle(static_cast<int>(w))) - centre).squaredNorm(), w);
      }
    ring_begin = ring_end;
  }
  if (found.size() > count) {  // the `count` nearest, in no particular order (the fit does not care)
    std::nth_element(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(count), found.end());
    found.resize(count);
  }
  std::vector<Vec3> neighbours;
  neighbours.reserve(found.size() + 1);  // the caller adds the vertex itself
  for (const auto& [squared, index] : found) neighbours.push_back(point(mesh, TriMesh::VertexHandle(static_cast<int>(index))));
  return neighbours;
}

// v's faces split at the creases into fans. OpenMesh turns clockwise around v: the face of
// outgoing halfedge h_k lies between h_(k-1) and h_k, so a crease at h_k closes the current fan.
std::vector<std::vector<TriMesh::FaceHandle>> fans_between_creases(const TriMesh& mesh, TriMesh::VertexHandle v,
                                                                   const std::vector<char>& crease) {
  std::vector<TriMesh::HalfedgeHandle> outgoing;
  for (auto h = mesh.cvoh_cwbegin(v); h != mesh.cvoh_cwend(v); ++h) outgoing.push_back(*h);
  auto is_crease = [&](TriMesh::HalfedgeHandle h) { return crease[static_cast<std::size_t>(mesh.edge_handle(h).idx())] != 0; };
  std::size_t start = 0;  // the first fan starts right after a crease, so none wraps around
  while (!is_crease(outgoing[start])) ++start;
  std::vector<std::vector<TriMesh::FaceHandle>> fans(1);
  for (std::size_t k = 1; k <= outgoing.size(); ++k) {
    const auto h = outgoing[(start + k) % outgoing.size()];
    if (mesh.face_handle(h).is_valid()) fans.back().push_back(mesh.face_handle(h));
    if (is_crease(h) && k < outgoing.size()) fans.emplace_back();
  }
  return fans;
}

// The local surface of vertex p: the tangent-frame height map (local_height_map.h) of p and its
// neighbours, a cubic weighted by a Gaussian of the distance to p, and its weighted RMS residual
// (how well one smooth surface explains the sites: the noise, or a crease it cannot follow).
struct LocalSurface {
  LocalHeightMap map;
  double residual = 0;
};

LocalSurface fit_local_surface(const Vec3& p, std::vector<Vec3> sites, double mean_edge, double smoothing) {
  sites.push_back(p);
  const double inverse_variance = 1 / std::pow(kBandwidth * mean_edge, 2);
  Eigen::VectorXd weights(static_cast<Eigen::Index>(sites.size()));
  for (std::size_t j = 0; j < sites.size(); ++j)
    weights[static_cast<Eigen::Index>(j)] = std::exp(-0.5 * (sites[j] - p).squaredNorm() * inverse_variance);
  LocalSurface surface{LocalHeightMap(sites, HeightMapPolynomial::cubic, smoothing, weights)};
  double weighted = 0;
  for (std::size_t j = 0; j < sites.size(); ++j) {
    const Vec3 local = surface.map.frame().to_local(sites[j]);
    weighted += weights[static_cast<Eigen::Index>(j)] * std::pow(local.z() - surface.map.spline().evaluate(local.x(), local.y()), 2);
  }
  surface.residual = std::sqrt(weighted / weights.sum());
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
  const std::vector<Vec3> normals = filtered_face_normals(mesh);
  const double cos_limit = std::cos(params.feature_angle_deg * M_PI / 180);
  const FeatureMap features{normals, crease_edges(mesh, normals, cos_limit), cos_limit};
  const std::size_t n = mesh.n_vertices();
  std::vector<Vec3> moved(n);
  std::vector<std::size_t> creases(n, 0);
  constexpr double kUnfitted = -1;
  std::vector<double> residual(n, kUnfitted);
  std::atomic<std::size_t> feature_line{0}, corners{0}, boundary{0}, unfitted{0}, noise_creases{0};
  const VertexGraph graph = vertex_graph(mesh, features);
  // The local surface of vertex i through `neighbours` (v excluded), if they hold one.
  auto fitted = [&](std::size_t i, std::vector<Vec3> neighbours, const Ring& ring) -> std::optional<LocalSurface> {
    const TriMesh::VertexHandle v(static_cast<int>(i));
    if (neighbours.size() + 1 < kFewestSites) return std::nullopt;
    try {
      return fit_local_surface(point(mesh, v), std::move(neighbours), ring.mean_edge, params.smoothing);
    } catch (const InvalidInput&) {  // sites on one cubic curve, or coinciding: no surface
      return std::nullopt;
    }
  };
  // A move longer than the vertex's mean edge is refused: a local surface that is not a graph over
  // its frame (a thin part folded into the neighbourhood) can throw the vertex far.
  auto place = [&](std::size_t i, const Vec3& target, const Ring& ring) {
    if ((target - moved[i]).norm() > ring.mean_edge) {
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
    const std::optional<LocalSurface> surface =
        fitted(i, nearby_vertices(mesh, graph, static_cast<std::uint32_t>(i), cos_limit, false, params.neighbors), ring);
    if (!surface) {
      ++unfitted;
      return;
    }
    if (place(i, onto_surface(*surface, moved[i], ring, params.relaxation), ring)) residual[i] = surface->residual;
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
        fitted(i, nearby_vertices(mesh, graph, static_cast<std::uint32_t>(i), -1.0, true, params.neighbors), ring);
    if (across && across->residual < kCreaseResidual * noise_level) {
      ++noise_creases;
      place(i, onto_surface(*across, moved[i], ring, params.relaxation), ring);
      return;
    }
    if (creases[i] != 2) {
      ++corners;
      return;
    }
    const auto fans = fans_between_creases(mesh, v, features.crease);
    auto side = [&](const std::vector<TriMesh::FaceHandle>& fan) {
      return fitted(i, same_side_neighbours(mesh, v, fan, features, params.neighbors), ring);
    };
    const std::optional<LocalSurface> first = side(fans[0]), second = side(fans[1]);
    if (!first || !second) {
      ++unfitted;
      return;
    }
    Vec3 x = moved[i];
    for (int round = 0; round < 4; ++round) x = second->map.project(first->map.project(x));
    if (place(i, x, ring)) ++feature_line;
  });
  counts = {feature_line, corners, boundary, unfitted, noise_creases};
  return moved;
}

}  // namespace meshprep
