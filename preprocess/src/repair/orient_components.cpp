#include "repair/orient_components.h"

#include <array>
#include <cstdint>
#include <queue>
#include <utility>
#include <vector>

namespace meshprep::detail {
namespace {

void flip(Triangle& t) { std::swap(t[1], t[2]); }

// Six times the signed volume the faces enclose (the divergence theorem over their cones from 0).
double six_volume(const TriangleSoup& soup, const std::vector<std::uint32_t>& faces) {
  double sum = 0;
  for (const std::uint32_t f : faces) {
    const Triangle& t = soup.triangles[f];
    sum += soup.points[t[0]].dot(soup.points[t[1]].cross(soup.points[t[2]]));
  }
  return sum;
}

}  // namespace

OrientCounts orient_components(TriangleSoup& soup, const std::vector<FaceEdge>& uses) {
  OrientCounts counts;
  // For each face, its manifold edges' other face and whether the two ran the edge the same way
  // in the input (at most three, in place: no allocation per face); border and non-manifold edges
  // join nothing (and keep a component open).
  struct Link {
    std::uint32_t other = UINT32_MAX;
    bool same_direction = false;
  };
  std::vector<std::array<Link, 3>> links(soup.triangles.size());
  const auto link = [&links](std::uint32_t face, Link l) {
    for (Link& slot : links[face])
      if (slot.other == UINT32_MAX) {
        slot = l;
        return;
      }
  };
  std::vector<char> open(soup.triangles.size(), 0);
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i == 2) {
      const bool same = uses[i].forward == uses[i + 1].forward;
      link(uses[i].face, {uses[i + 1].face, same});
      link(uses[i + 1].face, {uses[i].face, same});
    } else {
      for (std::size_t k = i; k < j; ++k) open[uses[k].face] = 1;
    }
    i = j;
  }
  std::vector<char> flipped(soup.triangles.size(), 0), reached(soup.triangles.size(), 0);
  for (std::uint32_t seed = 0; seed < soup.triangles.size(); ++seed) {
    if (reached[seed]) continue;
    ++counts.components;
    std::vector<std::uint32_t> component{seed};
    bool closed = true;
    reached[seed] = 1;
    std::queue<std::uint32_t> queue;
    queue.push(seed);
    while (!queue.empty()) {
      const std::uint32_t f = queue.front();
      queue.pop();
      closed = closed && !open[f];
      for (const Link& l : links[f]) {
        if (l.other == UINT32_MAX || reached[l.other]) continue;
        reached[l.other] = 1;
        // Agreeing faces run a shared edge in opposite directions.
        flipped[l.other] = static_cast<char>(flipped[f] ^ l.same_direction);
        component.push_back(l.other);
        queue.push(l.other);
      }
    }
    for (const std::uint32_t f : component)
      if (flipped[f]) {
        flip(soup.triangles[f]);
        ++counts.flipped_faces;
      }
    if (closed && six_volume(soup, component) < 0) {
      for (const std::uint32_t f : component) flip(soup.triangles[f]);
      ++counts.inverted_components;
    }
  }
  return counts;
}

}  // namespace meshprep::detail
