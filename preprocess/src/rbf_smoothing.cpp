#include "rbf_smoothing.h"

#include "meshprep/core/errors.h"
#include "meshprep/preprocess/local_height_map.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace meshprep {
namespace {

constexpr int kRings = 3;  // how far a neighbourhood reaches (in edges)

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
  for (const auto f : mesh.faces()) {
    auto corner = mesh.cfv_begin(f);
    const Vec3 a = point(mesh, *corner), b = point(mesh, *++corner), c = point(mesh, *++corner);
    const Vec3 cross = (b - a).cross(c - a);
    const auto i = static_cast<std::size_t>(f.idx());
    areas[i] = 0.5 * cross.norm();
    normals[i] = areas[i] > 0 ? Vec3(cross.normalized()) : Vec3::Zero();
    centroids[i] = (a + b + c) / 3;
  }
  // The faces around each face (sharing a vertex), once for all rounds (compressed rows).
  std::vector<std::size_t> first(n + 1, 0);
  std::vector<int> around;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t begin = around.size();
    for (const auto v : mesh.fv_range(TriMesh::FaceHandle(static_cast<int>(i))))
      for (const auto g : mesh.vf_range(v))
        if (std::find(around.begin() + static_cast<std::ptrdiff_t>(begin), around.end(), g.idx()) == around.end())
          around.push_back(g.idx());
    first[i + 1] = around.size();
  }
  constexpr double kSigmaNormal = 0.35;
  constexpr int kIterations = 5;
  std::vector<Vec3> next(n);
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
      Vec3 sum = Vec3::Zero();
      for (std::size_t k = first[i]; k < first[i + 1]; ++k) {
        const auto j = static_cast<std::size_t>(around[k]);
        const double dc = (centroids[j] - centroids[i]).norm() / sigma_centre;
        const double dn = (normals[j] - normals[i]).norm() / kSigmaNormal;
        sum += areas[j] * std::exp(-0.5 * (dc * dc + dn * dn)) * normals[j];
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
  for (const auto e : mesh.edges()) {
    if (mesh.is_boundary(e)) continue;
    const auto f0 = mesh.face_handle(mesh.halfedge_handle(e, 0)), f1 = mesh.face_handle(mesh.halfedge_handle(e, 1));
    crease[static_cast<std::size_t>(e.idx())] =
        normals[static_cast<std::size_t>(f0.idx())].dot(normals[static_cast<std::size_t>(f1.idx())]) < cos_limit;
  }
  return crease;
}

// Where the neighbourhood of a vertex may reach: not across a crease, not to a face turned more
// than the feature angle from the side it starts on (a crease that fades out, or the far side of
// a corner, would otherwise be reached around the end of the crease line).
struct FeatureMap {
  std::vector<Vec3> normals;  // unit face normals
  std::vector<char> crease;   // per edge
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
  const std::size_t kept = std::min(count, found.size());
  std::partial_sort(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(kept), found.end());
  std::vector<Vec3> neighbours;
  for (std::size_t k = 0; k < kept; ++k) neighbours.push_back(point(mesh, TriMesh::VertexHandle(found[k].second)));
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

}  // namespace

std::vector<Vec3> rbf_smoothing_step(const TriMesh& mesh, const SmoothParams& params, RbfIterationCounts& counts) {
  FeatureMap features;
  features.normals = filtered_face_normals(mesh);
  features.cos_limit = std::cos(params.feature_angle_deg * M_PI / 180);
  features.crease = crease_edges(mesh, features.normals, features.cos_limit);
  const std::vector<char>& crease = features.crease;
  std::vector<Vec3> moved(mesh.n_vertices());
  std::atomic<std::size_t> feature_line{0}, corners{0}, boundary{0}, unfitted{0};
  tbb::parallel_for(std::size_t(0), mesh.n_vertices(), [&](std::size_t i) {
    const TriMesh::VertexHandle v(static_cast<int>(i));
    moved[i] = point(mesh, v);
    if (mesh.status(v).deleted() || mesh.is_isolated(v)) return;
    if (mesh.is_boundary(v)) {
      ++boundary;
      return;
    }
    std::size_t creases = 0;
    for (const auto e : mesh.ve_range(v)) creases += crease[static_cast<std::size_t>(e.idx())];
    if (creases == 1 || creases > 2) {
      ++corners;
      return;
    }
    // The quadratic polynomial needs 6 sites (8: some margin against sites near one conic); the
    // smoothing spline keeps planes and quadrics.
    auto surface = [&](const std::vector<TriMesh::FaceHandle>& side) {
      const std::vector<Vec3> neighbours = same_side_neighbours(mesh, v, side, features, params.neighbors);
      if (neighbours.size() < 8) throw InvalidInput("too few neighbours");
      return LocalHeightMap(neighbours, HeightMapPolynomial::quadratic, params.smoothing);
    };
    try {
      if (creases == 0) {
        // Only the motion along the vertex's (filtered) normal is kept: the tangential part of the
        // projection would drift the vertices along the surface and spoil the triangles' shapes.
        std::vector<TriMesh::FaceHandle> faces;
        Vec3 normal = Vec3::Zero();
        for (const auto f : mesh.vf_range(v)) {
          faces.push_back(f);
          normal += features.normals[static_cast<std::size_t>(f.idx())];
        }
        normal.normalize();
        moved[i] += (surface(faces).project(moved[i]) - moved[i]).dot(normal) * normal;
      } else {
        // On a feature line: alternate projections onto the two sides converge to their
        // intersection, so the edge stays sharp (a few rounds: the sides are nearly transverse).
        const auto fans = fans_between_creases(mesh, v, crease);
        const LocalHeightMap first = surface(fans[0]), second = surface(fans[1]);
        Vec3 x = moved[i];
        for (int round = 0; round < 4; ++round) x = second.project(first.project(x));
        moved[i] = x;
        ++feature_line;
      }
    } catch (const InvalidInput&) {  // degenerate or too small a neighbourhood: the vertex stays
      moved[i] = point(mesh, v);
      ++unfitted;
      return;
    }
    // A local surface that is not a graph over its frame (a thin part folded into the
    // neighbourhood) can throw the vertex far: a move longer than the vertex's mean edge is refused.
    double edges = 0;
    int valence = 0;
    for (const auto u : mesh.vv_range(v)) {
      edges += (point(mesh, u) - point(mesh, v)).norm();
      ++valence;
    }
    if ((moved[i] - point(mesh, v)).norm() > edges / valence) {
      moved[i] = point(mesh, v);
      ++unfitted;
    }
  });
  counts = {feature_line, corners, boundary, unfitted};
  return moved;
}

}  // namespace meshprep
