#include "meshprep/quality/topology.h"

#include "meshprep/core/bucket_sort.h"
#include "meshprep/core/union_find.h"
#include "meshprep/quality/face_edges.h"

#include <algorithm>
#include <numeric>

namespace meshprep {
namespace {

constexpr std::size_t kMaxListed = 100;  // offending faces listed per problem

void list_face(std::vector<std::size_t>& list, std::size_t face) {
  if (list.size() < kMaxListed) list.push_back(face);
}

bool repeats_index(const Triangle& t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; }

// Corner id of vertex v in face f: 3 f + local index.
std::uint32_t corner(const SoupView& soup, std::uint32_t f, std::uint32_t v) {
  const Triangle& t = soup.triangles[f];
  return 3 * f + (t[0] == v ? 0 : t[1] == v ? 1 : 2);
}

// Faces over the same three vertices as an earlier face. The face indices are sorted by their
// vertex sets (then index), by their smallest vertex's runs (bucket_sort.h), so that copies sit
// together and the first of each run is the one kept: 4 bytes a face, where a hash set of the sets
// took 53.
void count_duplicates(const SoupView& soup, Topology& topo) {
  const auto vertex_set = [&](std::uint32_t f) {
    Triangle t = soup.triangles[f];
    std::sort(t.begin(), t.end());
    return t;
  };
  std::vector<std::uint32_t> order(soup.triangles.size());
  std::iota(order.begin(), order.end(), std::uint32_t{0});
  sort_by_buckets(
      order, [&](std::uint32_t f) { return vertex_set(f)[0]; },
      [&](std::uint32_t f, std::uint32_t g) {
        const Triangle a = vertex_set(f), b = vertex_set(g);
        return a < b || (a == b && f < g);
      });
  std::vector<std::size_t> copies;
  for (std::size_t i = 1; i < order.size(); ++i)
    if (vertex_set(order[i]) == vertex_set(order[i - 1])) copies.push_back(order[i]);
  std::sort(copies.begin(), copies.end());
  topo.duplicate_faces = copies.size();
  for (std::size_t f : copies) list_face(topo.duplicate_face_indices, f);
}

}  // namespace

Topology analyze_topology(const SoupView& soup) {
  Topology topo;
  const std::size_t n_faces = soup.triangles.size(), n_points = soup.points.size();
  std::vector<char> used(n_points, 0);
  std::size_t valid_faces = 0;
  for (const Triangle& t : soup.triangles) {
    for (auto v : t) used[v] = 1;
    if (repeats_index(t)) {
      list_face(topo.repeated_index_face_indices, static_cast<std::size_t>(&t - soup.triangles.data()));
      ++topo.repeated_index_faces;
    } else {
      ++valid_faces;
    }
  }
  topo.referenced_vertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
  topo.isolated_vertices = n_points - topo.referenced_vertices;

  const std::vector<FaceEdge> edges = sorted_face_edges(soup);
  detail::UnionFind faces(n_faces), corners(3 * n_faces), border_vertices(n_points);
  std::vector<char> on_border(n_points, 0);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t k = i;
    while (k < edges.size() && edges[k].key == edges[i].key) ++k;
    const std::size_t uses = k - i;
    const auto a = static_cast<std::uint32_t>(edges[i].key >> 32), b = static_cast<std::uint32_t>(edges[i].key);
    ++topo.edges;
    if (uses == 1) {
      ++topo.border_edges;
      list_face(topo.border_edge_faces, edges[i].face);
      border_vertices.unite(a, b);
      on_border[a] = on_border[b] = 1;
    } else if (uses > 2) {
      ++topo.non_manifold_edges;
      for (std::size_t q = i; q < k; ++q) list_face(topo.non_manifold_edge_faces, edges[q].face);
    } else if (edges[i].forward == edges[i + 1].forward) {
      ++topo.inconsistent_edges;
      list_face(topo.inconsistent_edge_faces, edges[i].face);
      list_face(topo.inconsistent_edge_faces, edges[i + 1].face);
    }
    // Faces across an edge are connected, and their corners at the edge's ends lie in one fan.
    for (std::size_t q = i + 1; q < k; ++q) {
      faces.unite(edges[i].face, edges[q].face);
      corners.unite(corner(soup, edges[i].face, a), corner(soup, edges[q].face, a));
      corners.unite(corner(soup, edges[i].face, b), corner(soup, edges[q].face, b));
    }
    i = k;
  }

  // A vertex is non-manifold when its corners fall into more than one fan.
  std::vector<std::uint32_t> first_fan(n_points, UINT32_MAX);
  std::vector<char> non_manifold_vertex(n_points, 0);
  for (std::uint32_t f = 0; f < n_faces; ++f) {
    const Triangle& t = soup.triangles[f];
    if (repeats_index(t)) continue;
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t fan = corners.find(3 * f + static_cast<std::uint32_t>(c));
      if (first_fan[t[c]] == UINT32_MAX) first_fan[t[c]] = fan;
      else if (first_fan[t[c]] != fan) non_manifold_vertex[t[c]] = 1;
    }
  }
  topo.non_manifold_vertices = static_cast<std::size_t>(std::count(non_manifold_vertex.begin(), non_manifold_vertex.end(), 1));
  for (std::uint32_t f = 0; f < n_faces && topo.non_manifold_vertices > 0; ++f) {
    const Triangle& t = soup.triangles[f];
    if (non_manifold_vertex[t[0]] || non_manifold_vertex[t[1]] || non_manifold_vertex[t[2]])
      list_face(topo.non_manifold_vertex_faces, f);
  }
  for (std::uint32_t f = 0; f < n_faces; ++f)
    if (!repeats_index(soup.triangles[f]) && faces.find(f) == f) ++topo.components;
  for (std::uint32_t v = 0; v < n_points; ++v)
    if (on_border[v] && border_vertices.find(v) == v) ++topo.boundary_loops;
  count_duplicates(soup, topo);

  topo.closed = topo.border_edges == 0;
  topo.manifold = topo.non_manifold_edges == 0 && topo.non_manifold_vertices == 0 && topo.repeated_index_faces == 0;
  topo.oriented = topo.manifold && topo.inconsistent_edges == 0;
  topo.euler_characteristic = static_cast<long long>(topo.referenced_vertices) - static_cast<long long>(topo.edges) +
                              static_cast<long long>(valid_faces);
  if (topo.closed && topo.manifold)
    topo.genus = (2 * static_cast<long long>(topo.components) - topo.euler_characteristic) / 2;
  return topo;
}

}  // namespace meshprep
