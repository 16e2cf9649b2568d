#include "flat_boundary_tets.h"

#include "tet_faces.h"

#include "meshprep/fem/tet_quality.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace meshprep::improve {
namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;

Edge edge(std::uint32_t a, std::uint32_t b) { return a < b ? Edge(a, b) : Edge(b, a); }

// The reverse of a face: the same corners seen from its other side.
Triangle reversed(const Triangle& f) { return {f[0], f[2], f[1]}; }

}  // namespace

std::size_t remove_flat_boundary_tets(TetMesh& mesh) {
  const std::vector<std::size_t> flat = flat_tets(mesh);
  if (flat.empty()) return 0;
  const detail::TetFaces faces(mesh.tets);
  // The listed boundary faces by their corners, and the edges of the boundary (faces of one tet).
  std::map<Triangle, std::size_t> listed;
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) listed.emplace(detail::sorted(mesh.boundary_faces[f]), f);
  std::set<Edge> boundary_edges;
  for (const std::uint32_t tet_face : faces.single_tet_faces()) {
    const Triangle f = detail::face_of(mesh.tets[tet_face / 4], static_cast<int>(tet_face % 4));
    for (int k = 0; k < 3; ++k) boundary_edges.insert(edge(f[k], f[(k + 1) % 3]));
  }
  std::vector<char> removed(mesh.tets.size(), 0);
  std::size_t count = 0;
  for (const std::size_t t : flat) {
    const Tetrahedron& tet = mesh.tets[t];
    // Flat either way round, not inverted: an inverted tet is a tangle, not a plane.
    const Vec3 &a = mesh.points[tet[0]], &b = mesh.points[tet[1]], &c = mesh.points[tet[2]], &d = mesh.points[tet[3]];
    if (certainly_positive(a, b, d, c)) continue;
    std::vector<int> outer, inner;  // the tet's faces on the boundary, and those shared with a tet
    for (int k = 0; k < 4; ++k) {
      const std::size_t first = faces.find(detail::sorted(detail::face_of(tet, k)));
      (faces.group_size(first) == 1 ? outer : inner).push_back(k);
    }
    if (outer.size() != 2) continue;
    const Triangle old_a = detail::face_of(tet, outer[0]), old_b = detail::face_of(tet, outer[1]);
    const auto listed_a = listed.find(detail::sorted(old_a)), listed_b = listed.find(detail::sorted(old_b));
    if (listed_a == listed.end() || listed_b == listed.end()) continue;
    const int tag = mesh.boundary_tags[listed_a->second];
    if (mesh.boundary_tags[listed_b->second] != tag) continue;
    // An interface between regions among the inner faces would be listed twice.
    if (listed.count(detail::sorted(detail::face_of(tet, inner[0]))) ||
        listed.count(detail::sorted(detail::face_of(tet, inner[1]))))
      continue;
    // Two faces of a tet share the edge of the two corners neither is opposite: the boundary's
    // faces meet at the inner faces' corners, and the inner faces at the outer faces' corners.
    const Edge old_diagonal = edge(tet[inner[0]], tet[inner[1]]);
    const Edge new_diagonal = edge(tet[outer[0]], tet[outer[1]]);
    if (boundary_edges.count(new_diagonal)) continue;
    // Of neighbouring flat tets one is removed per call (the faces it exposes are looked up anew
    // by the next).
    bool touches_removed = false;
    for (const int k : inner) {
      const std::size_t first = faces.find(detail::sorted(detail::face_of(tet, k)));
      for (std::size_t e = first; e < first + faces.group_size(first); ++e)
        touches_removed = touches_removed || removed[faces.entries()[e].tet_face / 4];
    }
    if (touches_removed) continue;
    removed[t] = 1;
    ++count;
    boundary_edges.erase(old_diagonal);
    boundary_edges.insert(new_diagonal);
    // The inner faces become boundary faces, outward from the tets that keep them.
    mesh.boundary_faces[listed_a->second] = reversed(detail::face_of(tet, inner[0]));
    mesh.boundary_faces[listed_b->second] = reversed(detail::face_of(tet, inner[1]));
    listed.erase(listed_a);
    listed.erase(listed_b);
  }
  if (count == 0) return 0;
  std::size_t kept = 0;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    if (!removed[t]) {
      mesh.tets[kept] = mesh.tets[t];
      mesh.tet_regions[kept] = mesh.tet_regions[t];
      ++kept;
    }
  mesh.tets.resize(kept);
  mesh.tet_regions.resize(kept);
  return count;
}

}  // namespace meshprep::improve
