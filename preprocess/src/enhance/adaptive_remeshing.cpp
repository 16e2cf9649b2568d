#include "enhance/adaptive_remeshing.h"

#include "enhance/reference_cover.h"

#include "shared/triangle_angles.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <queue>
#include <utility>

namespace meshprep::detail {
namespace {

using VertexHandle = TriMesh::VertexHandle;
using EdgeHandle = TriMesh::EdgeHandle;
using HalfedgeHandle = TriMesh::HalfedgeHandle;

// Botsch & Kobbelt's thresholds: an edge is split above 4/3 of the target and collapsed under 4/5,
// so that neither operation's result is at once the other's candidate.
constexpr double kSplitAbove = 4.0 / 3.0;
constexpr double kCollapseBelow = 4.0 / 5.0;
// A sweep of collapses is repeated while it removes something, at most this often.
constexpr int kMaxSweeps = 10;
// A move or collapse may turn a face by at most 60 degrees (as the enhancement's other guards).
constexpr double kMaxTurnCosine = 0.5;
// The time limit is asked at every this many steps of a sweep (a split, a flip, an edge or vertex
// visited): a sweep over a large surface takes seconds, the question a function call.
constexpr std::size_t kStepsBetweenPolls = 256;

Vec3 point(const TriMesh& mesh, VertexHandle v) { return to_eigen(mesh.point(v)); }

class Remesher {
 public:
  Remesher(TriMesh& mesh, SurfaceConstraints& constraints, const SizingField& sizing, const RemeshRules& rules)
      : mesh_(mesh), constraints_(constraints), sizing_(sizing), rules_(rules),
        min_angle_cosine_(std::cos(rules.target_min_angle_deg * M_PI / 180.0)),
        bent_(bent_reference_edges(constraints.reference_bvh().surface())) {
    mesh_.add_property(size_);
    faces_at_start_ = mesh_.n_faces();
    for (const auto v : mesh_.vertices()) measure_size(v);
  }
  ~Remesher() { mesh_.remove_property(size_); }
  Remesher(const Remesher&) = delete;
  Remesher& operator=(const Remesher&) = delete;

  RemeshCounts run() {
    // A CAD export's flat faces are fans and needles: made Delaunay first, and kept so after each
    // split, the splits refine them instead of putting a vertex on every needle for the collapses
    // to take away (example005: 51,000 splits and 45,000 collapses for 12,000 faces; 10,000 and
    // 3,900 with the flips).
    for (const auto e : mesh_.edges()) flip_stack_.push_back(e);
    flip_planar_to_delaunay([](EdgeHandle) {});
    for (std::size_t i = 0; i < rules_.iterations && !out_of_time(true); ++i) {
      split_long_edges();
      collapse_short_edges();
      flip_toward_valence_six();
      relax_tangentially();
    }
    mesh_.garbage_collection();
    return counts_;
  }

 private:
  double target(EdgeHandle e) const {
    const auto h = mesh_.halfedge_handle(e, 0);
    return 0.5 * (mesh_.property(size_, mesh_.from_vertex_handle(h)) + mesh_.property(size_, mesh_.to_vertex_handle(h)));
  }
  double target(VertexHandle a, VertexHandle b) const { return 0.5 * (mesh_.property(size_, a) + mesh_.property(size_, b)); }

  // The faces now: each split adds two, each collapse removes two (one each on the boundary: an
  // estimate there).
  std::size_t live_faces() const { return faces_at_start_ + 2 * counts_.splits - std::min(2 * counts_.collapses, faces_at_start_ + 2 * counts_.splits); }

  void measure_size(VertexHandle v) { mesh_.property(size_, v) = sizing_(point(mesh_, v)); }

  // Whether rules_.out_of_time said stop: asked at every kStepsBetweenPolls-th call, or at once
  // with `now`. Once it has, every sweep ends at its next step (each step leaves a valid mesh).
  bool out_of_time(bool now = false) {
    if (!counts_.stopped_by_time && rules_.out_of_time && (now || ++steps_ % kStepsBetweenPolls == 0))
      counts_.stopped_by_time = rules_.out_of_time();
    return counts_.stopped_by_time;
  }

  double gap(const Vec3& p) const { return std::sqrt(constraints_.closest_on_reference(p).squared_distance); }

  // Longest first (relative to the target), as Rivara's longest-edge bisection: a needle's long
  // edges are halved before its neighbours' short ones, so that fewer slivers are made to be
  // collapsed again (example001: 173,000 splits in midpoint sweeps, most of them undone).
  void split_long_edges() {
    struct Long {
      float excess;  // length over target
      int edge;
      bool operator<(const Long& o) const { return excess != o.excess ? excess < o.excess : edge > o.edge; }
    };
    std::priority_queue<Long> queue;
    // Compared in single precision, edges equal up to round-off tie and go by index: the order,
    // and the mesh, stay the same when the part is scaled (a CAD part's many equal edges).
    const auto excess_of = [&](EdgeHandle e) { return static_cast<float>(mesh_.calc_edge_length(e) / target(e)); };
    const auto push = [&](EdgeHandle e) {
      const float excess = excess_of(e);
      if (excess > kSplitAbove) queue.push({excess, e.idx()});
    };
    for (const auto e : mesh_.edges()) push(e);
    while (!queue.empty() && !out_of_time()) {
      if (rules_.max_faces > 0 && live_faces() >= rules_.max_faces) {
        counts_.stopped_at_max_faces = true;
        return;
      }
      const Long top = queue.top();
      queue.pop();
      const EdgeHandle e(top.edge);
      if (mesh_.status(e).deleted() || excess_of(e) != top.excess) continue;  // stale
      const VertexHandle m = constraints_.is_feature(e) ? constraints_.split_feature_edge(e)
                                                        : constraints_.split_surface_edge(e, true);
      if (constraints_.role(m) == VertexRole::Surface) settle(m);
      measure_size(m);
      ++counts_.splits;
      for (const HalfedgeHandle out : mesh_.voh_range(m))
        if (mesh_.face_handle(out).is_valid()) flip_stack_.push_back(mesh_.edge_handle(mesh_.next_halfedge_handle(out)));
      flip_planar_to_delaunay(push);
      for (const HalfedgeHandle out : mesh_.voh_range(m)) {
        push(mesh_.edge_handle(out));
        if (mesh_.face_handle(out).is_valid()) push(mesh_.edge_handle(mesh_.next_halfedge_handle(out)));
      }
    }
  }

  // Puts a new Surface vertex (at its edge's midpoint) onto the reference, unless the closest
  // reference face faces another way or the move would turn one of its faces: across a thin part
  // the far wall may be the closest (animation: splits that never shortened an edge ran to the
  // face limit).
  void settle(VertexHandle m) {
    const Vec3 middle = point(mesh_, m);
    Vec3 normal = Vec3::Zero();
    for (const auto f : mesh_.vf_range(m)) normal += to_eigen(mesh_.calc_face_normal(f));
    if (constraints_.reference_normal(constraints_.closest_on_reference(middle).face).dot(normal) <= kMaxTurnCosine * normal.norm())
      return;  // the closest point is on a wall across, not under the edge
    const Vec3 onto = constraints_.project(m, middle);
    if (!turns_faces(m, onto)) mesh_.set_point(m, to_openmesh(onto));
  }

  // Whether moving v to x turns one of its faces by more than kMaxTurnCosine allows (or flattens it).
  bool turns_faces(VertexHandle v, const Vec3& x) const { return vertex_move(mesh_, v, x, kMaxTurnCosine, HeightField{}).turns; }

  // Flips the edges on flip_stack_, and the edges each flip exposes, while they join two coplanar
  // faces (within kCoplanarCosine) and are not locally Delaunay: Lawson's flips, which end at the
  // Delaunay triangulation of a plane's vertices and do not move the surface (within the bound,
  // checked as a flip toward valence 6 checks it). Calls flipped(e) for each flipped edge.
  template <class Flipped>
  void flip_planar_to_delaunay(const Flipped& flipped) {
    while (!flip_stack_.empty() && !out_of_time()) {
      const EdgeHandle e = flip_stack_.back();
      flip_stack_.pop_back();
      if (mesh_.status(e).deleted() || mesh_.is_boundary(e) || constraints_.is_feature(e) || !mesh_.is_flip_ok(e)) continue;
      const HalfedgeHandle h0 = mesh_.halfedge_handle(e, 0), h1 = mesh_.halfedge_handle(e, 1);
      const Vec3 a = point(mesh_, mesh_.from_vertex_handle(h0)), b = point(mesh_, mesh_.to_vertex_handle(h0));
      const Vec3 c = point(mesh_, mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h0)));
      const Vec3 d = point(mesh_, mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h1)));
      const Vec3 n0 = area_normal(a, b, c), n1 = area_normal(b, a, d);
      if (!(n0.dot(n1) >= kCoplanarCosine * n0.norm() * n1.norm())) continue;
      if (!flips_to_delaunay(a, b, c, d)) continue;
      // The quad must be convex: both new faces facing as the old.
      const Vec3 m0 = area_normal(a, d, c), m1 = area_normal(d, b, c);
      if (!(m0.dot(n0) > 0) || !(m1.dot(n0) > 0)) continue;
      if (std::abs((0.5 * (a + b) - 0.5 * (c + d)).dot((n0 + n1).normalized())) > rules_.max_deviation) continue;
      mesh_.flip(e);
      ++counts_.flips;
      flipped(e);
      for (const HalfedgeHandle h : {mesh_.next_halfedge_handle(h0), mesh_.prev_halfedge_handle(h0), mesh_.next_halfedge_handle(h1),
                                     mesh_.prev_halfedge_handle(h1)})
        flip_stack_.push_back(mesh_.edge_handle(h));
    }
  }

  void collapse_short_edges() {
    for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
      std::size_t collapses = 0;
      for (std::size_t i = 0; i < mesh_.n_edges() && !out_of_time(); ++i) {
        const EdgeHandle e(static_cast<int>(i));
        if (mesh_.status(e).deleted() || mesh_.calc_edge_length(e) >= kCollapseBelow * target(e)) continue;
        for (int side : {0, 1}) {
          const HalfedgeHandle h = mesh_.halfedge_handle(e, side);
          if (!may_collapse(h)) continue;
          mesh_.collapse(h);
          ++collapses;
          break;
        }
      }
      counts_.collapses += collapses;
      if (collapses == 0) break;
    }
  }

  // Whether h's start may be removed into its end (kept where it is): the roles allow it, no
  // feature edge is merged away, no new edge is long, no face turns, and the surface stays within
  // the bound both ways.
  bool may_collapse(HalfedgeHandle h) const {
    const VertexHandle v = mesh_.from_vertex_handle(h), w = mesh_.to_vertex_handle(h);
    const VertexRole role = constraints_.role(v);
    if (role == VertexRole::Fixed || !mesh_.is_collapse_ok(h)) return false;
    // A Line vertex goes only along its line, into the next vertex on it.
    if (role == VertexRole::Line && (!constraints_.is_feature(mesh_.edge_handle(h)) || constraints_.role(w) == VertexRole::Surface))
      return false;
    if (constraints_.collapse_merges_feature(h)) return false;
    const Vec3 x = point(mesh_, v), y = point(mesh_, w);
    std::vector<Corners> fan_before, fan_after;
    std::vector<std::pair<Vec3, Vec3>> rim;
    for (const HalfedgeHandle out : mesh_.voh_range(v)) {
      const VertexHandle p = mesh_.to_vertex_handle(out);
      if (p != w && (point(mesh_, p) - y).norm() > kSplitAbove * target(w, p)) return false;
      if (!mesh_.face_handle(out).is_valid()) continue;
      const VertexHandle q = mesh_.to_vertex_handle(mesh_.next_halfedge_handle(out));
      const Vec3 b = point(mesh_, p), c = point(mesh_, q);
      fan_before.push_back({x, b, c});
      rim.emplace_back(b, c);
      if (p == w || q == w) continue;  // vanishes
      const Vec3 before = area_normal(x, b, c), after = area_normal(y, b, c);
      if (!(after.dot(before) > kMaxTurnCosine * after.norm() * before.norm())) return false;
      if (gap((y + b + c) / 3.0) > rules_.max_deviation || gap(0.5 * (y + b)) > rules_.max_deviation) return false;
      fan_after.push_back({y, b, c});
    }
    return keeps_reference_covered(constraints_, fan_before, fan_after, rim, rules_.max_deviation, &bent_);
  }

  int valence_excess(VertexHandle v, int change) const {
    const int ideal = mesh_.is_boundary(v) ? 4 : 6;
    return std::abs(static_cast<int>(mesh_.valence(v)) + change - ideal);
  }

  void flip_toward_valence_six() {
    for (const auto e : mesh_.edges()) {
      if (out_of_time()) return;
      if (mesh_.is_boundary(e) || constraints_.is_feature(e) || !mesh_.is_flip_ok(e)) continue;
      const HalfedgeHandle h0 = mesh_.halfedge_handle(e, 0), h1 = mesh_.halfedge_handle(e, 1);
      const VertexHandle va = mesh_.from_vertex_handle(h0), vb = mesh_.to_vertex_handle(h0);
      const VertexHandle vc = mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h0));
      const VertexHandle vd = mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h1));
      if (mesh_.valence(va) <= 3 || mesh_.valence(vb) <= 3) continue;
      const int before = valence_excess(va, 0) + valence_excess(vb, 0) + valence_excess(vc, 0) + valence_excess(vd, 0);
      const int after = valence_excess(va, -1) + valence_excess(vb, -1) + valence_excess(vc, 1) + valence_excess(vd, 1);
      if (after >= before) continue;
      const Vec3 a = point(mesh_, va), b = point(mesh_, vb), c = point(mesh_, vc), d = point(mesh_, vd);
      // Faces (a, b, c) and (b, a, d) become (a, d, c) and (d, b, c).
      const Vec3 n = area_normal(a, b, c) + area_normal(b, a, d);
      const Vec3 m0 = area_normal(a, d, c), m1 = area_normal(d, b, c);
      if (!(m0.dot(n) > kMaxTurnCosine * m0.norm() * n.norm()) || !(m1.dot(n) > kMaxTurnCosine * m1.norm() * n.norm())) continue;
      const double old_cosine = std::max(smallest_angle_cosine(a, b, c), smallest_angle_cosine(b, a, d));
      const double new_cosine = std::max(smallest_angle_cosine(a, d, c), smallest_angle_cosine(d, b, c));
      if (new_cosine > std::max(old_cosine, min_angle_cosine_)) continue;
      // The flip swaps a tetrahedron's pairs of faces: its height is how far the surface moves.
      if (std::abs((0.5 * (a + b) - 0.5 * (c + d)).dot(n.normalized())) > rules_.max_deviation) continue;
      if (gap(0.5 * (c + d)) > rules_.max_deviation) continue;
      if (!keeps_reference_covered(constraints_, {{a, b, c}, {b, a, d}}, {{a, d, c}, {d, b, c}}, {{a, c}, {c, b}, {b, d}, {d, a}},
                                   rules_.max_deviation, &bent_))
        continue;
      mesh_.flip(e);
      ++counts_.flips;
    }
  }

  // Each vertex toward the area-weighted centroid of its faces, in its tangent plane (along its
  // line for a Line vertex), then back onto the reference; a move that turns a face or carries an
  // edge's midpoint beyond the bound is not made.
  void relax_tangentially() {
    for (const auto v : mesh_.vertices()) {
      if (out_of_time()) return;
      const VertexRole role = constraints_.role(v);
      if (role == VertexRole::Fixed) continue;
      const Vec3 x = point(mesh_, v);
      Vec3 centroid = Vec3::Zero(), normal = Vec3::Zero();
      double area = 0;
      for (const auto f : mesh_.vf_range(v)) {
        const auto h = mesh_.halfedge_handle(f);
        const Vec3 n = area_normal(point(mesh_, mesh_.from_vertex_handle(h)), point(mesh_, mesh_.to_vertex_handle(h)),
                                   point(mesh_, mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h))));
        const double a = 0.5 * n.norm();
        centroid += a * to_eigen(mesh_.calc_face_centroid(f));
        normal += n;
        area += a;
      }
      if (!(area > 0)) continue;
      const Vec3 step = centroid / area - x;
      Vec3 moved;
      if (role == VertexRole::Line) {
        const auto [p, q] = constraints_.line_neighbours(v);
        if (!p.is_valid() || !q.is_valid()) continue;
        const Vec3 along = (point(mesh_, q) - point(mesh_, p)).normalized();
        moved = x + along * step.dot(along);
      } else {
        const Vec3 n = normal.normalized();
        moved = x + step - n * step.dot(n);
      }
      const Vec3 onto = constraints_.project(v, moved);
      if (!onto.allFinite() || turns_faces(v, onto) || !keeps_faithful(v, onto)) continue;
      mesh_.set_point(v, to_openmesh(onto));
      measure_size(v);
    }
  }

  // Whether moving v to x keeps its edges' midpoints within the bound of the reference, and the
  // reference under its faces covered.
  bool keeps_faithful(VertexHandle v, const Vec3& x) const {
    std::vector<Corners> before, after;
    std::vector<std::pair<Vec3, Vec3>> rim;
    const Vec3 old = point(mesh_, v);
    for (const HalfedgeHandle out : mesh_.voh_range(v)) {
      const Vec3 b = point(mesh_, mesh_.to_vertex_handle(out));
      if (gap(0.5 * (x + b)) > rules_.max_deviation) return false;
      if (!mesh_.face_handle(out).is_valid()) continue;
      const Vec3 c = point(mesh_, mesh_.to_vertex_handle(mesh_.next_halfedge_handle(out)));
      before.push_back({old, b, c});
      after.push_back({x, b, c});
      rim.emplace_back(b, c);
    }
    return keeps_reference_covered(constraints_, before, after, rim, rules_.max_deviation, &bent_);
  }

  TriMesh& mesh_;
  SurfaceConstraints& constraints_;
  const SizingField& sizing_;
  const RemeshRules& rules_;
  const double min_angle_cosine_;
  const std::vector<std::uint8_t> bent_;  // the reference's bent edges (reference_cover.h)
  OpenMesh::VPropHandleT<double> size_;
  RemeshCounts counts_;
  std::size_t faces_at_start_ = 0;
  std::size_t steps_ = 0;  // out_of_time's count
  std::vector<EdgeHandle> flip_stack_;  // flip_planar_to_delaunay's work, kept between splits
};

}  // namespace

RemeshCounts remesh_to_sizing(TriMesh& mesh, SurfaceConstraints& constraints, const SizingField& sizing,
                              const RemeshRules& rules) {
  Remesher remesher(mesh, constraints, sizing, rules);
  return remesher.run();
}

}  // namespace meshprep::detail
