#include "tet_complex.h"

#include "exact_orientation.h"
#include "tet_objective.h"

#include "meshprep/core/errors.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cassert>
#include <string>
#include <unordered_set>

namespace meshprep::improve {
namespace {

using Face = std::array<VertexId, 3>;

// The same oriented face whatever corner it starts at: rotated so that its smallest index is first.
Face canonical(const Face& f) {
  if (f[1] < f[0] && f[1] < f[2]) return {f[1], f[2], f[0]};
  if (f[2] < f[0] && f[2] < f[1]) return {f[2], f[0], f[1]};
  return f;
}
Face reversed(const Face& canonical_face) { return {canonical_face[0], canonical_face[2], canonical_face[1]}; }

struct FaceKey {
  VertexId a, b, c;  // sorted
  bool operator==(const FaceKey& o) const { return a == o.a && b == o.b && c == o.c; }
};
struct FaceKeyHash {
  std::size_t operator()(const FaceKey& k) const {
    std::uint64_t h = k.a;
    h = h * 0x9E3779B97F4A7C15ull ^ k.b;
    h = h * 0x9E3779B97F4A7C15ull ^ k.c;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};
FaceKey key_of(VertexId a, VertexId b, VertexId c) {
  if (a > b) std::swap(a, b);
  if (b > c) std::swap(b, c);
  if (a > b) std::swap(a, b);
  return {a, b, c};
}

bool has_corner(const Tetrahedron& t, VertexId v) { return t[0] == v || t[1] == v || t[2] == v || t[3] == v; }

int corner_of(const Tetrahedron& t, VertexId v) {
  for (int c = 0; c < 4; ++c)
    if (t[c] == v) return c;
  return -1;
}

// The corner of t that is not on the face f.
int corner_off_face(const Tetrahedron& t, const Face& f) {
  for (int c = 0; c < 4; ++c)
    if (t[c] != f[0] && t[c] != f[1] && t[c] != f[2]) return c;
  return -1;
}

// Is (t[p[0]], t[p[1]], t[p[2]], t[p[3]]) an even permutation of t's corners?
bool even_permutation(const int p[4]) {
  int inversions = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) inversions += p[i] > p[j];
  return inversions % 2 == 0;
}

}  // namespace

std::array<VertexId, 3> outward_face(const Tetrahedron& t, int c) {
  switch (c) {
    case 0: return {t[1], t[2], t[3]};
    case 1: return {t[0], t[3], t[2]};
    case 2: return {t[0], t[1], t[3]};
    default: return {t[0], t[2], t[1]};
  }
}

TetComplex::TetComplex(const TetMesh& mesh, double obtuse_weight, const std::function<bool()>& cancelled)
    : points_(mesh.points),
      free_(mesh.points.size(), 1),
      removed_(mesh.points.size(), 0),
      vertex_tet_(mesh.points.size(), kNoTet),
      tets_(mesh.tets),
      neighbours_(mesh.tets.size(), {kNoTet, kNoTet, kNoTet, kNoTet}),
      constrained_(mesh.tets.size(), 0),
      regions_(mesh.tet_regions),
      quality_(mesh.tets.size()),
      alive_(mesh.tets.size(), 1),
      obtuse_weight_(obtuse_weight) {
  // Vertex -> incident tets (CSR), to find each face's other tet.
  const std::size_t n_tets = tets_.size();
  std::vector<std::uint32_t> start(points_.size() + 1, 0), incident(4 * n_tets);
  for (const Tetrahedron& t : tets_)
    for (const VertexId v : t) ++start[v + 1];
  for (std::size_t v = 0; v < points_.size(); ++v) start[v + 1] += start[v];
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (TetId t = 0; t < n_tets; ++t)
      for (const VertexId v : tets_[t]) incident[fill[v]++] = t;
  }
  std::unordered_set<FaceKey, FaceKeyHash> listed;
  listed.reserve(mesh.boundary_faces.size());
  for (const Triangle& f : mesh.boundary_faces) listed.insert(key_of(f[0], f[1], f[2]));

  std::atomic<std::size_t> bad_face{~std::size_t(0)};
  std::atomic<bool> overlapping{false};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n_tets, 2048), [&](const auto& range) {
    if (cancelled && cancelled()) throw Cancelled("tet improvement stopped");
    for (std::size_t t = range.begin(); t != range.end(); ++t) {
      for (int c = 0; c < 4; ++c) {
        const Face f = outward_face(tets_[t], c);
        VertexId pivot = f[0];
        for (const VertexId v : f)
          if (start[v + 1] - start[v] < start[pivot + 1] - start[pivot]) pivot = v;
        TetId other = kNoTet;
        bool too_many = false;
        for (std::uint32_t k = start[pivot]; k < start[pivot + 1]; ++k) {
          const TetId u = incident[k];
          if (u == t || !has_corner(tets_[u], f[0]) || !has_corner(tets_[u], f[1]) || !has_corner(tets_[u], f[2])) continue;
          too_many = other != kNoTet;
          other = u;
        }
        if (too_many) {
          bad_face = 4 * t + static_cast<std::size_t>(c);
          continue;
        }
        neighbours_[t][c] = other;
        bool constrained = other == kNoTet || regions_[other] != regions_[t];
        if (other != kNoTet) {
          const Face mine = canonical(f);
          if (canonical(outward_face(tets_[other], corner_off_face(tets_[other], f))) != reversed(mine)) overlapping = true;
          if (!constrained && !listed.empty()) constrained = listed.count(key_of(f[0], f[1], f[2])) > 0;
        }
        if (constrained) constrained_[t] |= static_cast<std::uint8_t>(1u << c);
      }
      quality_[t] = quality_of(tets_[t]);
    }
  });
  if (bad_face != ~std::size_t(0)) {
    const std::size_t t = bad_face / 4;
    throw InvalidInput("tet mesh: a face of tet " + std::to_string(t) + " is shared by more than two tets");
  }
  if (overlapping) throw InvalidInput("tet mesh: two tets sharing a face are oriented inconsistently (they overlap)");

  for (TetId t = 0; t < n_tets; ++t)
    for (int c = 0; c < 4; ++c) {
      vertex_tet_[tets_[t][c]] = t;
      if (constrained(t, c))
        for (const VertexId v : outward_face(tets_[t], c)) free_[v] = 0;
    }
}

double TetComplex::quality_of(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) const {
  return biased_min_sine(a, b, c, d, obtuse_weight_);
}

double TetComplex::quality_of(const Tetrahedron& t) const {
  return quality_of(points_[t[0]], points_[t[1]], points_[t[2]], points_[t[3]]);
}

void TetComplex::star(VertexId v, std::vector<TetId>& out) const {
  out.clear();
  const TetId first = vertex_tet_[v];
  if (first == kNoTet) return;
  out.push_back(first);
  for (std::size_t next = 0; next < out.size(); ++next) {
    const TetId t = out[next];
    for (int c = 0; c < 4; ++c) {
      const TetId n = neighbours_[t][c];
      if (tets_[t][c] == v || n == kNoTet || std::find(out.begin(), out.end(), n) != out.end()) continue;
      out.push_back(n);
    }
  }
}

bool TetComplex::edge_ring(TetId t, VertexId a, VertexId b, std::size_t max_ring, std::vector<TetId>& tets,
                           std::vector<VertexId>& ring) const {
  tets.clear();
  ring.clear();
  const int ca = corner_of(tets_[t], a), cb = corner_of(tets_[t], b);
  int others[2], k = 0;
  for (int c = 0; c < 4; ++c)
    if (c != ca && c != cb) others[k++] = c;
  const int order[4] = {ca, cb, others[0], others[1]};
  VertexId next = tets_[t][even_permutation(order) ? others[1] : others[0]];  // (a, b, c, next) positive
  TetId current = t;
  do {
    if (tets.size() == max_ring) return false;
    const VertexId c = tets_[current][0] + tets_[current][1] + tets_[current][2] + tets_[current][3] - a - b - next;
    tets.push_back(current);
    ring.push_back(c);
    // Across the face (a, b, next), opposite c.
    const int opposite = corner_of(tets_[current], c);
    if (constrained(current, opposite)) return false;
    const TetId n = neighbours_[current][opposite];
    const VertexId after = tets_[n][0] + tets_[n][1] + tets_[n][2] + tets_[n][3] - a - b - next;
    current = n;
    next = after;
  } while (current != t);
  return true;
}

TetId TetComplex::new_slot() {
  if (!free_slots_.empty()) {
    const TetId t = free_slots_.back();
    free_slots_.pop_back();
    return t;
  }
  tets_.emplace_back();
  neighbours_.push_back({kNoTet, kNoTet, kNoTet, kNoTet});
  constrained_.push_back(0);
  regions_.push_back(0);
  quality_.push_back(0);
  alive_.push_back(0);
  return static_cast<TetId>(tets_.size() - 1);
}

bool TetComplex::take_slot(TetId t) {
  const auto found = std::find(free_slots_.rbegin(), free_slots_.rend(), t);
  if (found == free_slots_.rend()) return false;
  *found = free_slots_.back();
  free_slots_.pop_back();
  return true;
}

bool TetComplex::replace(const std::vector<TetId>& old, const std::vector<Tetrahedron>& fresh,
                         const std::vector<TetId>* slots) {
  return replace_tets(old, fresh, slots, kNoVertex);
}

bool TetComplex::remove_vertex(VertexId v, const std::vector<TetId>& star, const std::vector<Tetrahedron>& fresh) {
  if (!free_[v] || !replace_tets(star, fresh, nullptr, v)) return false;
  vertex_tet_[v] = kNoTet;
  removed_[v] = 1;
  any_removed_ = true;
  return true;
}

bool TetComplex::replace_tets(const std::vector<TetId>& old, const std::vector<Tetrahedron>& fresh,
                              const std::vector<TetId>* slots, VertexId removed) {
  if (old.empty() || fresh.empty() || (slots && slots->size() != fresh.size())) return false;
  const int region = regions_[old[0]];
  for (const TetId t : old)
    if (!alive_[t] || regions_[t] != region) return false;

  struct OuterFace {
    Face face;  // canonical, oriented out of the old space
    TetId outside;
    bool constrained;
    int used_by = -1;  // 4 * fresh tet + corner
  };
  std::vector<OuterFace> outer;
  std::vector<VertexId> old_corners;
  for (const TetId t : old)
    for (int c = 0; c < 4; ++c) {
      if (std::find(old_corners.begin(), old_corners.end(), tets_[t][c]) == old_corners.end())
        old_corners.push_back(tets_[t][c]);
      const TetId n = neighbours_[t][c];
      if (n != kNoTet && std::find(old.begin(), old.end(), n) != old.end()) continue;
      outer.push_back({canonical(outward_face(tets_[t], c)), n, constrained(t, c)});
    }

  struct InnerFace {
    Face face;
    int owner;     // 4 * fresh tet + corner
    int partner = -1;
  };
  std::vector<InnerFace> inner;
  for (std::size_t k = 0; k < fresh.size(); ++k) {
    const Tetrahedron& t = fresh[k];
    if (t[0] == t[1] || t[0] == t[2] || t[0] == t[3] || t[1] == t[2] || t[1] == t[3] || t[2] == t[3]) return false;
    if (!positively_oriented(points_[t[0]], points_[t[1]], points_[t[2]], points_[t[3]])) return false;
    for (int c = 0; c < 4; ++c) {
      const int owner = static_cast<int>(4 * k) + c;
      const Face f = canonical(outward_face(t, c));
      const Face back = reversed(f);
      bool matched = false;
      for (OuterFace& o : outer) {
        if (o.face == back) return false;  // the fresh tet would stick out of the old space
        if (o.face != f) continue;
        if (o.used_by >= 0) return false;
        o.used_by = owner;
        matched = true;
        break;
      }
      if (matched) continue;
      for (InnerFace& i : inner) {
        if (i.face == f) return false;  // two fresh tets on the same side of a face: they overlap
        if (i.face == back && i.partner < 0) {
          i.partner = owner;
          matched = true;
          break;
        }
      }
      if (!matched) inner.push_back({f, owner});
    }
  }
  for (const OuterFace& o : outer)
    if (o.used_by < 0) return false;
  for (const InnerFace& i : inner)
    if (i.partner < 0) return false;
  for (const VertexId v : old_corners) {
    bool kept = false;
    for (const Tetrahedron& t : fresh) kept = kept || has_corner(t, v);
    if (kept == (v == removed)) return false;
  }

  if (slots)
    for (const TetId t : *slots)
      if (t >= tets_.size() || (alive_[t] && std::find(old.begin(), old.end(), t) == old.end())) return false;

  // Valid: apply.
  for (const TetId t : old) {
    alive_[t] = 0;
    free_slots_.push_back(t);
  }
  created_.resize(fresh.size());
  for (std::size_t k = 0; k < fresh.size(); ++k) {
    TetId t;
    if (slots) {
      t = (*slots)[k];
      [[maybe_unused]] const bool taken = take_slot(t);
      assert(taken);
    } else {
      t = new_slot();
    }
    created_[k] = t;
    tets_[t] = fresh[k];
    regions_[t] = region;
    constrained_[t] = 0;
    alive_[t] = 1;
    quality_[t] = quality_of(fresh[k]);
    for (const VertexId v : fresh[k]) vertex_tet_[v] = t;
  }
  for (const InnerFace& i : inner) {
    link(created_[i.owner / 4], i.owner % 4, created_[i.partner / 4]);
    link(created_[i.partner / 4], i.partner % 4, created_[i.owner / 4]);
  }
  for (const OuterFace& o : outer) {
    const TetId t = created_[o.used_by / 4];
    const int c = o.used_by % 4;
    link(t, c, o.outside);
    if (o.constrained) constrained_[t] |= static_cast<std::uint8_t>(1u << c);
    if (o.outside != kNoTet) link(o.outside, corner_off_face(tets_[o.outside], o.face), t);
  }
  return true;
}

void TetComplex::link(TetId t, int corner, TetId other) { neighbours_[t][corner] = other; }

VertexId TetComplex::add_point(const Vec3& p) {
  points_.push_back(p);
  free_.push_back(1);
  removed_.push_back(0);
  vertex_tet_.push_back(kNoTet);
  return static_cast<VertexId>(points_.size() - 1);
}

void TetComplex::discard_point([[maybe_unused]] VertexId v) {
  assert(v + 1 == points_.size() && vertex_tet_[v] == kNoTet);
  points_.pop_back();
  free_.pop_back();
  removed_.pop_back();
  vertex_tet_.pop_back();
}

void TetComplex::move_point(VertexId v, const Vec3& p, const std::vector<TetId>& star) {
  points_[v] = p;
  for (const TetId t : star) quality_[t] = quality_of(tets_[t]);
}

TetMesh TetComplex::to_mesh(const TetMesh& original) const {
  // New index of each point (the removed ones are free, so no boundary face names them).
  std::vector<VertexId> index(points_.size());
  TetMesh mesh;
  mesh.points.reserve(points_.size());
  for (VertexId v = 0; v < points_.size(); ++v) {
    index[v] = static_cast<VertexId>(mesh.points.size());
    if (!removed_[v]) mesh.points.push_back(points_[v]);
  }
  mesh.tets.reserve(live_tets());
  mesh.tet_regions.reserve(live_tets());
  for (TetId t = 0; t < tets_.size(); ++t) {
    if (!alive_[t]) continue;
    const Tetrahedron& c = tets_[t];
    mesh.tets.push_back(any_removed_ ? Tetrahedron{index[c[0]], index[c[1]], index[c[2]], index[c[3]]} : c);
    mesh.tet_regions.push_back(regions_[t]);
  }
  mesh.boundary_faces = original.boundary_faces;
  if (any_removed_)
    for (Triangle& f : mesh.boundary_faces) f = {index[f[0]], index[f[1]], index[f[2]]};
  mesh.boundary_tags = original.boundary_tags;
  mesh.boundary_names = original.boundary_names;
  mesh.region_names = original.region_names;
  // tet_edge_nodes stays empty: improve_tets refuses second-order meshes, so `original` has none.
  return mesh;
}

}  // namespace meshprep::improve
