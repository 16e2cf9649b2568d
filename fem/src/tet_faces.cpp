#include "tet_faces.h"

#include "meshprep/fem/tet_boundary.h"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

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

bool same_orientation(const Triangle& a, const Triangle& b) {
  for (int i = 0; i < 3; ++i)
    if (a[0] == b[i]) return a[1] == b[(i + 1) % 3];
  return false;
}

std::vector<std::uint32_t> tet_faces_of(const std::vector<Tetrahedron>& tets, const std::vector<Triangle>& faces) {
  std::vector<std::pair<Triangle, std::size_t>> keys(faces.size());
  std::uint32_t largest = 0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    keys[f] = {sorted(faces[f]), f};
    largest = std::max(largest, keys[f].first[2]);
  }
  std::sort(keys.begin(), keys.end());
  std::vector<bool> listed(keys.empty() ? 0 : std::size_t{largest} + 1, false);
  for (const auto& key : keys)
    for (const std::uint32_t v : key.first) listed[v] = true;
  const auto corner_listed = [&](std::uint32_t v) { return v < listed.size() && listed[v]; };
  std::vector<std::uint32_t> found(faces.size(), kNoTetFace);
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (int k = 0; k < 4; ++k) {
      const Triangle face = face_of(tets[t], k);
      if (!corner_listed(face[0]) || !corner_listed(face[1]) || !corner_listed(face[2])) continue;
      const Triangle key = sorted(face);
      for (auto it = std::lower_bound(keys.begin(), keys.end(), std::make_pair(key, std::size_t{0}));
           it != keys.end() && it->first == key; ++it) {
        std::uint32_t& tet_face = found[it->second];
        const Triangle& wanted = faces[it->second];
        if (tet_face == kNoTetFace ||
            (!same_orientation(wanted, face_of(tets[tet_face / 4], static_cast<int>(tet_face % 4))) &&
             same_orientation(wanted, face)))
          tet_face = static_cast<std::uint32_t>(4 * t + static_cast<std::size_t>(k));
      }
    }
  return found;
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
