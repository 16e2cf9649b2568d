#include "tet_faces.h"

#include "meshprep/fem/tet_boundary.h"

#include <algorithm>
#include <map>

namespace meshprep {
namespace detail {

// Seen from outside a positive tet (p1 - p0) . ((p2 - p0) x (p3 - p0)) > 0, each face runs
// counter-clockwise: e.g. for the unit tet, face 0 (1, 2, 3) has normal (1, 1, 1).
constexpr int outward_face[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

Triangle face_of(const Tetrahedron& tet, int k) {
  return {tet[outward_face[k][0]], tet[outward_face[k][1]], tet[outward_face[k][2]]};
}

Triangle sorted(Triangle corners) {
  std::sort(corners.begin(), corners.end());
  return corners;
}

TetFaces::TetFaces(const std::vector<Tetrahedron>& tets) {
  entries_.reserve(4 * tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (int k = 0; k < 4; ++k) entries_.push_back({sorted(face_of(tets[t], k)), static_cast<std::uint32_t>(4 * t + k)});
  std::sort(entries_.begin(), entries_.end(),
            [](const Entry& a, const Entry& b) { return a.key != b.key ? a.key < b.key : a.tet_face < b.tet_face; });
}

std::size_t TetFaces::group_size(std::size_t first) const {
  std::size_t last = first + 1;
  while (last < entries_.size() && entries_[last].key == entries_[first].key) ++last;
  return last - first;
}

std::size_t TetFaces::find(const Triangle& key) const {
  const auto it = std::lower_bound(entries_.begin(), entries_.end(), key,
                                   [](const Entry& e, const Triangle& k) { return e.key < k; });
  return it != entries_.end() && it->key == key ? static_cast<std::size_t>(it - entries_.begin()) : entries_.size();
}

std::vector<std::uint32_t> TetFaces::single_tet_faces(const std::vector<bool>* excluded) const {
  std::vector<std::uint32_t> once;
  for (std::size_t first = 0; first < entries_.size();) {
    const std::size_t size = group_size(first);
    if (size == 1 && !(excluded && (*excluded)[first])) once.push_back(entries_[first].tet_face);
    first += size;
  }
  std::sort(once.begin(), once.end());
  return once;
}

}  // namespace detail

TriangleSoup boundary_surface(const TetMesh& mesh) {
  // A face's tag by its corners (in any rotation and orientation).
  const auto key = [](Triangle t) {
    std::sort(t.begin(), t.end());
    return t;
  };
  std::map<Triangle, int> tag_of;
  for (std::size_t f = 0; f < mesh.boundary_faces.size() && f < mesh.boundary_tags.size(); ++f)
    tag_of.emplace(key(mesh.boundary_faces[f]), mesh.boundary_tags[f]);
  TriangleSoup soup;
  soup.triangles = tet_boundary(mesh);
  std::vector<std::uint32_t> index(mesh.points.size(), UINT32_MAX);
  for (const Triangle& t : soup.triangles)
    for (const std::uint32_t v : t) index[v] = 0;
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (index[v] == 0) {
      index[v] = static_cast<std::uint32_t>(soup.points.size());
      soup.points.push_back(mesh.points[v]);
    }
  soup.patches.reserve(soup.triangles.size());
  for (Triangle& t : soup.triangles) {
    const auto tag = tag_of.find(key(t));
    soup.patches.push_back(tag == tag_of.end() ? 1 : tag->second);
    for (std::uint32_t& v : t) v = index[v];
  }
  const bool untagged = std::all_of(soup.patches.begin(), soup.patches.end(), [](int tag) { return tag == 1; });
  if (untagged && !mesh.boundary_names.count(1)) soup.patches.clear();
  else soup.patch_names = mesh.boundary_names;
  return soup;
}

std::vector<Triangle> tet_boundary(const TetMesh& mesh) {
  const std::vector<std::uint32_t> once = detail::TetFaces(mesh.tets).single_tet_faces();
  std::vector<Triangle> boundary;
  boundary.reserve(once.size());
  for (const std::uint32_t tet_face : once)
    boundary.push_back(detail::face_of(mesh.tets[tet_face / 4], static_cast<int>(tet_face % 4)));
  return boundary;
}

}  // namespace meshprep
