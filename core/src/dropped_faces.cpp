// Why mesh_from_soup could not add a face: the soup around it, read the way OpenMesh's add_face
// fails (two corners at one vertex, a second copy, a third face on an edge, an edge traversed
// twice the same way, a second fan of faces at a corner).
#include "meshprep/core/mesh.h"

#include <algorithm>
#include <string>
#include <unordered_map>

namespace meshprep {
namespace {

std::string vertex_text(std::uint32_t v) { return "vertex " + std::to_string(v); }

bool has_directed_edge(const Triangle& t, std::uint32_t from, std::uint32_t to) {
  for (int k = 0; k < 3; ++k)
    if (t[k] == from && t[(k + 1) % 3] == to) return true;
  return false;
}

bool has_vertex(const Triangle& t, std::uint32_t v) { return t[0] == v || t[1] == v || t[2] == v; }

// Fans of faces around vertex v: faces that share an edge at v are in one fan.
std::size_t fans_at(const TriangleSoup& soup, std::uint32_t v) {
  std::vector<std::size_t> parent;
  std::unordered_map<std::uint32_t, std::size_t> face_by_spoke;  // an edge v-w: a face on it
  const auto root = [&parent](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const Triangle& t : soup.triangles) {
    if (!has_vertex(t, v)) continue;
    const std::size_t face = parent.size();
    parent.push_back(face);
    for (const std::uint32_t w : t) {
      if (w == v) continue;
      const auto [it, added] = face_by_spoke.try_emplace(w, face);
      if (!added) parent[root(face)] = root(it->second);
    }
  }
  std::size_t fans = 0;
  for (std::size_t i = 0; i < parent.size(); ++i) fans += root(i) == i;
  return fans;
}

}  // namespace

std::string dropped_face_problem(const TriangleSoup& soup, std::size_t face) {
  const Triangle& t = soup.triangles[face];
  const std::string name = "face " + std::to_string(face);
  for (int k = 0; k < 3; ++k)
    if (t[k] == t[(k + 1) % 3]) return name + " has two corners at " + vertex_text(t[k]);
  Triangle sorted = t;
  std::sort(sorted.begin(), sorted.end());
  std::size_t edge_uses[3] = {0, 0, 0};
  std::size_t same_way = soup.triangles.size();  // a face traversing an edge of `face` the same way
  std::size_t same_way_edge = 0;
  for (std::size_t g = 0; g < soup.triangles.size(); ++g) {
    const Triangle& other = soup.triangles[g];
    Triangle other_sorted = other;
    std::sort(other_sorted.begin(), other_sorted.end());
    if (g != face && other_sorted == sorted) return name + " repeats face " + std::to_string(g);
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      if (!has_vertex(other, a) || !has_vertex(other, b)) continue;
      ++edge_uses[k];
      if (g != face && same_way == soup.triangles.size() && has_directed_edge(other, a, b)) {
        same_way = g;
        same_way_edge = static_cast<std::size_t>(k);
      }
    }
  }
  for (int k = 0; k < 3; ++k)
    if (edge_uses[k] > 2)
      return name + " makes the edge " + std::to_string(t[k]) + "-" + std::to_string(t[(k + 1) % 3]) +
             " non-manifold (" + std::to_string(edge_uses[k]) + " faces share it)";
  if (same_way < soup.triangles.size()) {
    const std::uint32_t a = t[same_way_edge], b = t[(same_way_edge + 1) % 3];
    return name + " is oriented against face " + std::to_string(same_way) + " (both run from " + vertex_text(a) +
           " to " + std::to_string(b) + ")";
  }
  for (const std::uint32_t v : t) {
    const std::size_t fans = fans_at(soup, v);
    if (fans > 1)
      return name + " makes " + vertex_text(v) + " non-manifold (" + std::to_string(fans) +
             " fans of faces meet there)";
  }
  return name + " cannot be added to a halfedge mesh";
}

std::string dropped_faces_problem(const TriangleSoup& soup, const MeshBuildReport& report) {
  if (report.dropped_faces.empty()) return {};
  const std::size_t more = report.dropped_faces.size() - 1;
  return dropped_face_problem(soup, report.dropped_faces.front()) +
         (more == 0 ? std::string()
                    : " (" + std::to_string(more) + (more == 1 ? " more face cannot" : " more faces cannot") +
                          " be added either)");
}

}  // namespace meshprep
