#include "boundary_slides.h"

#include "vertex_smoothing.h"

#include "meshprep/quality/triangle_bvh.h"
#include "meshprep/quality/triangle_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace meshprep::improve {
namespace {

constexpr double kRadiansPerDegree = M_PI / 180.0;
// An edge where the boundary's normals turn by more than this is a crease: its vertices slide
// along it only. Sliding across an edge that turns by theta moves the surface off itself by about
// sin(theta) times the step, which the deviation bound weighs anyway; past 30 degrees the edge is
// a feature of the part (CAD parts' edges turn by 90) that sliding across would round.
constexpr double kCreaseTurnDeg = 30;
// A boundary face turns by at most this from its first normal: enough for the slides of a curved
// surface's vertices (a face turns by about its step over the radius), far from a fold.
constexpr double kMaxFaceTurnDeg = 30;
// A boundary face's smallest angle stays at least the smaller of this and its first one: the
// surface report's count of faces under 10 degrees never rises, its smallest angle never falls.
// At 20 (the report's other count) the slides lost most of their gain on the corpus (bones 13.53,
// projection 10.92 instead of 14.89 and 11.83: bench/RESULTS.md "Boundary slides").
constexpr double kFaceAngleFloorDeg = 10;
// A slide that leaves the surface's conditions is tried again this many times, halved towards the
// start each time.
constexpr int kSurfaceHalvings = 4;

Vec3 face_normal(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a); }

}  // namespace

BoundarySlides::BoundarySlides(const TetComplex& mesh, const TetMesh& tagged, double max_deviation)
    : max_deviation_(max_deviation), first_points_(mesh.points()), kind_(mesh.points(), Kind::fixed) {
  for (VertexId v = 0; v < mesh.points(); ++v) first_points_[v] = mesh.point(v);
  std::vector<std::uint8_t> pinned(mesh.points(), 0);
  for (TetId t = 0; t < mesh.tet_slots(); ++t) {
    if (!mesh.alive(t)) continue;
    for (int c = 0; c < 4; ++c) {
      if (!mesh.constrained(t, c)) continue;
      const std::array<VertexId, 3> f = outward_face(mesh.tet(t), c);
      if (mesh.neighbour(t, c) == kNoTet) faces_.push_back(f);
      else
        for (const VertexId v : f) pinned[v] = 1;  // between regions, or a listed inner face
    }
  }
  first_normals_.resize(faces_.size());
  least_angles_deg_.resize(faces_.size());
  fan_start_.assign(mesh.points() + 1, 0);
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const auto& c = faces_[f];
    first_normals_[f] = face_normal(first_points_[c[0]], first_points_[c[1]], first_points_[c[2]]).normalized();
    least_angles_deg_[f] = std::min(kFaceAngleFloorDeg,
                                    triangle_shape(first_points_[c[0]], first_points_[c[1]], first_points_[c[2]]).min_angle_deg);
    for (const VertexId v : c) ++fan_start_[v + 1];
  }
  for (std::size_t v = 0; v < mesh.points(); ++v) fan_start_[v + 1] += fan_start_[v];
  fan_.resize(3 * faces_.size());
  {
    std::vector<std::uint32_t> fill(fan_start_.begin(), fan_start_.end() - 1);
    for (std::size_t f = 0; f < faces_.size(); ++f)
      for (const VertexId v : faces_[f]) fan_[fill[v]++] = static_cast<std::uint32_t>(f);
  }
  // The tags, when the boundary has more than one: a vertex between two patches is on a crease.
  std::map<std::array<VertexId, 3>, int> tags;
  if (std::adjacent_find(tagged.boundary_tags.begin(), tagged.boundary_tags.end(), std::not_equal_to<>()) !=
      tagged.boundary_tags.end())
    for (std::size_t k = 0; k < tagged.boundary_faces.size() && k < tagged.boundary_tags.size(); ++k) {
      std::array<VertexId, 3> key = tagged.boundary_faces[k];
      std::sort(key.begin(), key.end());
      tags[key] = tagged.boundary_tags[k];
    }
  const auto tag_of = [&](std::size_t f) {
    if (tags.empty()) return 0;
    std::array<VertexId, 3> key = faces_[f];
    std::sort(key.begin(), key.end());
    const auto found = tags.find(key);
    return found == tags.end() ? 0 : found->second;
  };

  crease_ends_.assign(mesh.points(), {kNoVertex, kNoVertex});
  std::vector<std::pair<VertexId, std::uint32_t>> edges;  // (neighbour, face) around a vertex
  for (VertexId v = 0; v < mesh.points(); ++v) {
    const std::uint32_t begin = fan_start_[v], end = fan_start_[v + 1];
    if (begin == end || pinned[v] || mesh.free_vertex(v)) continue;
    edges.clear();
    bool degenerate = false;
    for (std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t f = fan_[k];
      degenerate |= !first_normals_[f].allFinite();
      for (const VertexId w : faces_[f])
        if (w != v) edges.push_back({w, f});
    }
    if (degenerate) continue;
    // One disc around v: each neighbour on exactly two of its faces, and as many neighbours as faces.
    std::sort(edges.begin(), edges.end());
    bool disc = edges.size() == 2 * (end - begin);
    std::vector<VertexId> creases;
    for (std::size_t k = 0; disc && k < edges.size(); k += 2) {
      disc = edges[k].first == edges[k + 1].first && (k + 2 == edges.size() || edges[k + 2].first != edges[k].first);
      if (!disc) break;
      const std::uint32_t f = edges[k].second, g = edges[k + 1].second;
      const double turn = std::acos(std::clamp(first_normals_[f].dot(first_normals_[g]), -1.0, 1.0));
      if (turn > kCreaseTurnDeg * kRadiansPerDegree || tag_of(f) != tag_of(g)) creases.push_back(edges[k].first);
    }
    // Walking the fan from one face must reach every face: one disc, not two touching at v.
    if (disc) {
      std::size_t walked = 1;
      std::uint32_t face = fan_[begin];
      auto next_of = [&](std::uint32_t f) {  // the corner after v in face f
        const auto& c = faces_[f];
        return c[0] == v ? c[1] : c[1] == v ? c[2] : c[0];
      };
      auto prev_of = [&](std::uint32_t f) {
        const auto& c = faces_[f];
        return c[0] == v ? c[2] : c[1] == v ? c[0] : c[1];
      };
      for (;;) {
        const VertexId w = next_of(face);
        std::uint32_t following = face;
        for (std::uint32_t k = begin; k < end; ++k)
          if (fan_[k] != face && prev_of(fan_[k]) == w) following = fan_[k];
        if (following == face || following == fan_[begin]) break;
        face = following;
        ++walked;
      }
      disc = walked == end - begin;
    }
    if (!disc) continue;
    if (creases.empty()) {
      kind_[v] = Kind::surface;
    } else if (creases.size() == 2) {
      kind_[v] = Kind::crease;
      crease_ends_[v] = {creases[0], creases[1]};
    }
  }
}

std::array<Vec3, 3> BoundarySlides::corners(const TetComplex& mesh, std::size_t f, VertexId moved, const Vec3& p) const {
  std::array<Vec3, 3> q;
  for (int i = 0; i < 3; ++i) q[i] = faces_[f][i] == moved ? p : mesh.point(faces_[f][i]);
  return q;
}

double BoundarySlides::distance_to_first_fan(VertexId v, const Vec3& x) const {
  double best = std::numeric_limits<double>::infinity();
  for (std::uint32_t k = fan_start_[v]; k < fan_start_[v + 1]; ++k) {
    const auto& c = faces_[fan_[k]];
    const Vec3 q = closest_point_on_triangle(x, first_points_[c[0]], first_points_[c[1]], first_points_[c[2]]);
    best = std::min(best, (q - x).squaredNorm());
  }
  return std::sqrt(best);
}

double BoundarySlides::distance_to_fan(const TetComplex& mesh, VertexId v, VertexId moved, const Vec3& p,
                                       const Vec3& x) const {
  double best = std::numeric_limits<double>::infinity();
  for (std::uint32_t k = fan_start_[v]; k < fan_start_[v + 1]; ++k) {
    const std::array<Vec3, 3> q = corners(mesh, fan_[k], moved, p);
    best = std::min(best, (closest_point_on_triangle(x, q[0], q[1], q[2]) - x).squaredNorm());
  }
  return std::sqrt(best);
}

bool BoundarySlides::keeps_surface(const TetComplex& mesh, VertexId v, const Vec3& p) const {
  const double cos_turn = std::cos(kMaxFaceTurnDeg * kRadiansPerDegree);
  for (std::uint32_t k = fan_start_[v]; k < fan_start_[v + 1]; ++k) {
    const std::uint32_t f = fan_[k];
    const std::array<Vec3, 3> q = corners(mesh, f, v, p);
    const Vec3 n = face_normal(q[0], q[1], q[2]);
    if (!(n.norm() > 0) || n.normalized().dot(first_normals_[f]) < cos_turn) return false;
    if (!(triangle_shape(q[0], q[1], q[2]).min_angle_deg >= least_angles_deg_[f])) return false;
    // The samples: the centroid and the midpoints of the two edges at v, each near the first fans
    // of the face's corners (the face spans their first positions' neighbourhood).
    const int at = faces_[f][0] == v ? 0 : faces_[f][1] == v ? 1 : 2;
    const Vec3 samples[3] = {(q[0] + q[1] + q[2]) / 3, 0.5 * (p + q[(at + 1) % 3]), 0.5 * (p + q[(at + 2) % 3])};
    for (const Vec3& x : samples) {
      double d = std::numeric_limits<double>::infinity();
      for (const VertexId c : faces_[f]) d = std::min(d, distance_to_first_fan(c, x));
      if (!(d <= max_deviation_)) return false;
    }
  }
  // The first positions of v and its neighbours near the faces around them now.
  if (!(distance_to_fan(mesh, v, v, p, first_points_[v]) <= max_deviation_)) return false;
  for (std::uint32_t k = fan_start_[v]; k < fan_start_[v + 1]; ++k)
    for (const VertexId w : faces_[fan_[k]])
      if (w != v && !(distance_to_fan(mesh, w, v, p, first_points_[w]) <= max_deviation_)) return false;
  return true;
}

bool BoundarySlides::slide(TetComplex& mesh, VertexId v) const {
  SlideConstraint constraint;
  if (kind_[v] == Kind::surface) {
    // On the first fan: in its mean plane, then onto its nearest face.
    Vec3 normal = Vec3::Zero();
    for (std::uint32_t k = fan_start_[v]; k < fan_start_[v + 1]; ++k) {
      const auto& c = faces_[fan_[k]];
      normal += face_normal(first_points_[c[0]], first_points_[c[1]], first_points_[c[2]]);
    }
    normal.normalize();
    constraint.direction = [normal](const Vec3& g) { return Vec3(g - g.dot(normal) * normal); };
    constraint.position = [this, v](const Vec3& x) {
      Vec3 best = x;
      double nearest = std::numeric_limits<double>::infinity();
      for (std::uint32_t k = fan_start_[v]; k < fan_start_[v + 1]; ++k) {
        const auto& c = faces_[fan_[k]];
        const Vec3 q = closest_point_on_triangle(x, first_points_[c[0]], first_points_[c[1]], first_points_[c[2]]);
        if ((q - x).squaredNorm() < nearest) nearest = (q - x).squaredNorm(), best = q;
      }
      return best;
    };
  } else {
    // On the first crease: along the line through its two neighbours, then onto its two edges.
    const Vec3 a = first_points_[crease_ends_[v][0]], b = first_points_[crease_ends_[v][1]], o = first_points_[v];
    const Vec3 along = (b - a).normalized();
    constraint.direction = [along](const Vec3& g) { return Vec3(g.dot(along) * along); };
    constraint.position = [a, b, o](const Vec3& x) {
      const Vec3 p = closest_point_on_segment(x, a, o), q = closest_point_on_segment(x, o, b);
      return (p - x).squaredNorm() <= (q - x).squaredNorm() ? p : q;
    };
  }
  return smooth_vertex(mesh, v, &constraint, [&](const Vec3& p) { return keeps_surface(mesh, v, p); },
                       kSurfaceHalvings);
}

}  // namespace meshprep::improve
