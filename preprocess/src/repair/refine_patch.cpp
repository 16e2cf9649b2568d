#include "repair/refine_patch.h"

#include "repair/triangulate_hole.h"
#include "shared/triangle_angles.h"

#include <array>
#include <cmath>
#include <cstddef>

namespace meshprep::detail {
namespace {

// Liepa's density factor: a centroid this many times its distance to a corner beyond the local
// edge length means the face is too large for the surface around.
const double kDensity = std::sqrt(2.0);
// Exact ties (a regular grid around the hole) do not split, whatever the rounding at the scale.
constexpr double kMargin = 1 + 1e-9;
// Bounds on the split rounds and on the flip sweeps after each: Liepa's loop ends by itself (each
// round's faces are smaller), these only stop a pathological rim from running away.
constexpr int kMaxRounds = 64;
constexpr int kMaxSweeps = 64;

class Patch {
 public:
  Patch(std::vector<Vec3>& points, std::vector<Triangle>& faces, const std::unordered_set<std::uint64_t>& edges)
      : points_(points), faces_(faces), surface_edges_(edges) {
    for (std::size_t f = 0; f < faces_.size(); ++f) link(f);
  }

  // Splits face f at its centroid, vertex `centre`, then flips its old edges if they are not Delaunay.
  void split(std::size_t f, std::uint32_t centre) {
    const Triangle t = faces_[f];
    unlink(f);
    faces_[f] = {t[0], t[1], centre};
    link(f);
    for (int k = 1; k < 3; ++k) {
      faces_.push_back({t[k], t[(k + 1) % 3], centre});
      link(faces_.size() - 1);
    }
    for (int k = 0; k < 3; ++k) flip_if_not_delaunay(t[k], t[(k + 1) % 3]);
  }

  // One sweep over the inner edges; whether any flipped.
  bool relax() {
    std::vector<std::uint64_t> keys;
    keys.reserve(faces_of_edge_.size());
    for (const auto& entry : faces_of_edge_) keys.push_back(entry.first);
    bool flipped = false;
    for (const std::uint64_t key : keys)
      flipped |= flip_if_not_delaunay(static_cast<std::uint32_t>(key >> 32), static_cast<std::uint32_t>(key));
    return flipped;
  }

 private:
  static constexpr std::size_t kNone = SIZE_MAX;

  // An edge of more than two patch faces (a rim that passes a vertex twice can give one) is
  // crowded: it keeps its faces as they are, never flipped.
  void link(std::size_t f) {
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t key = edge_key(faces_[f][k], faces_[f][(k + 1) % 3]);
      auto& slots = faces_of_edge_.try_emplace(key, Slots{kNone, kNone}).first->second;
      if (slots[0] == kNone)
        slots[0] = f;
      else if (slots[1] == kNone)
        slots[1] = f;
      else
        crowded_.insert(key);
    }
  }

  void unlink(std::size_t f) {
    for (int k = 0; k < 3; ++k) {
      const auto found = faces_of_edge_.find(edge_key(faces_[f][k], faces_[f][(k + 1) % 3]));
      if (found == faces_of_edge_.end()) continue;
      Slots& slots = found->second;
      if (slots[0] == f) slots[0] = slots[1], slots[1] = kNone;
      if (slots[1] == f) slots[1] = kNone;
      if (slots[0] == kNone) faces_of_edge_.erase(found);
    }
  }

  // The edge a-b of two patch faces f = (a, b, c) and g = (b, a, d) becomes c-d: (a, d, c) and
  // (d, b, c) keep the orientation. Not if c-d is an edge already, or if a-b is Delaunay.
  bool flip_if_not_delaunay(std::uint32_t a, std::uint32_t b) {
    const auto found = faces_of_edge_.find(edge_key(a, b));
    if (found == faces_of_edge_.end() || found->second[1] == kNone) return false;  // a rim edge
    if (crowded_.count(found->first)) return false;
    std::size_t f = found->second[0], g = found->second[1];
    if (!runs(f, a, b)) std::swap(f, g);  // f runs a -> b
    if (!runs(f, a, b) || !runs(g, b, a)) return false;  // the two faces disagree in orientation
    const std::uint32_t c = opposite(f, a, b), d = opposite(g, a, b);
    if (c == d || surface_edges_.count(edge_key(c, d)) || faces_of_edge_.count(edge_key(c, d))) return false;
    const Vec3 &pa = points_[a], &pb = points_[b];
    if (!flips_to_delaunay(pa, pb, points_[c], points_[d])) return false;
    if (degenerate(a, d, c) || degenerate(d, b, c)) return false;  // c on a-b's line, or on a copy of d
    unlink(f);
    unlink(g);
    faces_[f] = {a, d, c};
    faces_[g] = {d, b, c};
    link(f);
    link(g);
    return true;
  }

  // Whether face f has the edge a -> b in its own orientation.
  bool runs(std::size_t f, std::uint32_t a, std::uint32_t b) const {
    for (int k = 0; k < 3; ++k)
      if (faces_[f][k] == a && faces_[f][(k + 1) % 3] == b) return true;
    return false;
  }

  bool degenerate(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
    const Vec3 u = points_[b] - points_[a], w = points_[c] - points_[a];
    return too_thin(u.cross(w).norm(), u, w);
  }

  std::uint32_t opposite(std::size_t f, std::uint32_t a, std::uint32_t b) const {
    for (const std::uint32_t v : faces_[f])
      if (v != a && v != b) return v;
    return a;
  }

  using Slots = std::array<std::size_t, 2>;
  std::vector<Vec3>& points_;
  std::vector<Triangle>& faces_;
  const std::unordered_set<std::uint64_t>& surface_edges_;
  std::unordered_map<std::uint64_t, Slots> faces_of_edge_;
  std::unordered_set<std::uint64_t> crowded_;
};

}  // namespace

void refine_patch(std::vector<Vec3>& points, std::unordered_map<std::uint32_t, double>& scale,
                  std::vector<Triangle>& patch, const std::unordered_set<std::uint64_t>& edges) {
  Patch mesh(points, patch, edges);
  for (int round = 0; round < kMaxRounds; ++round) {
    bool split = false;
    for (std::size_t f = 0, faces = patch.size(); f < faces; ++f) {
      const Triangle t = patch[f];
      const Vec3 centroid = (points[t[0]] + points[t[1]] + points[t[2]]) / 3;
      const double centroid_scale = (scale[t[0]] + scale[t[1]] + scale[t[2]]) / 3;
      bool large = true;
      for (const std::uint32_t v : t) {
        const double reach = kDensity * (centroid - points[v]).norm();
        large = large && reach > centroid_scale * kMargin && reach > scale[v] * kMargin;
      }
      if (!large) continue;
      const auto centre = static_cast<std::uint32_t>(points.size());
      points.push_back(centroid);
      scale[centre] = centroid_scale;
      mesh.split(f, centre);
      split = true;
    }
    if (!split) return;
    for (int sweep = 0; sweep < kMaxSweeps; ++sweep)
      if (!mesh.relax()) break;
  }
}

}  // namespace meshprep::detail
