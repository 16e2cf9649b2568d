#include "smooth/smoothing_neighbourhoods.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace meshprep::detail {
namespace {

constexpr int kRings = kSmoothingRings;

Vec3 point(const TriMesh& mesh, TriMesh::VertexHandle v) { return to_eigen(mesh.point(v)); }

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

}  // namespace

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

// OpenMesh turns clockwise around v: the face of
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

}  // namespace meshprep::detail
