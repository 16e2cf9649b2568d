#include "simplify/edge_collapse.h"

#include "simplify/banded_order.h"
#include "simplify/collapse_guard.h"
#include "simplify/indexed_heap.h"
#include "simplify/link_condition.h"
#include "shared/triangle_angles.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/mesh_patches.h"
#include "meshprep/preprocess/rbf/local_height_map.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

namespace meshprep::detail {
namespace {

using VertexHandle = TriMesh::VertexHandle;
using EdgeHandle = TriMesh::EdgeHandle;
using HalfedgeHandle = TriMesh::HalfedgeHandle;

// Bending cost = dQ (1 + mu Jhat) + eps Jhat (|e| / L)^2 with Jhat = (J / |e|) / median(J / |e|):
// mu and eps are the best of the prototype sweep (docs/simplification.md); the product form is
// scale-free where a fixed weight J + w Q needed w = 3 at 10 % and w = 300 at 30 %. dQ is the
// quadric error the collapse adds, Q_a+b(p) - Q_a(a) - Q_b(b) (at least 0), not the error the
// merged vertex carries (bunny00 at 10 %: RMS distance 1.63e-4 -> 1.54e-4). Two places keep the
// whole Q(p), where the error a vertex has gathered must keep further collapses away from it:
// - where the input's triangles are thin, it spreads the collapses out (blade at 10 %: radius
//   ratio p95 15.2 with dQ, 5.4 with Q);
// - on the boundary, it stops collapses piling up along the border (with dQ, a border face of the
//   Jacksboro terrain turned past vertical, and horizons' Hausdorff distance went 4.0e-3 -> 5.2e-3).
constexpr double kShapeWeight = 3.0;
constexpr double kShapeTieBreak = 1e-6;
// A collapse refused by the shape guard is tried again later (its neighbours may have moved) at
// this multiple of its cost, at most this many times before its neighbourhood changes.
constexpr double kRetryPenalty = 2.0;
constexpr unsigned char kMaxRetries = 3;
// How often a queue that ran dry before the target is restarted after reshaping the mesh.
constexpr int kMaxStuckRestarts = 8;
// A quadric minimiser farther than this many edge lengths from the midpoint is not trusted.
constexpr double kFarPlacement = 2.0;
// An input face with a smallest angle under this is thin (see the cost above).
const double kThinFaceCosine = std::cos(20.0 * M_PI / 180.0);
// The banded order of big meshes (banded_order.h): costs within 20 % of one another share a band,
// taken by blocks of 1,024 edge numbers (about 340 vertices): 0.82x the time at 1.2 M faces in
// alternating pairs (docs/simplification.md); bands of 5-30 % and blocks of 16-4,096 edges ran
// within the VM's noise of it.
constexpr double kCostBand = 1.2;
constexpr int kBlockShift = 10;

// Everything the queue keeps per edge, in one record: a collapse reads and writes it for a dozen
// edges at scattered places of the mesh, one or two cache lines each instead of one per array (at
// 1.2 M faces the arrays did not fit in the cache). The heap holds a copy of each queued edge's
// cost. The quadric placement is not kept: it is computed again, from the same end points and
// quadrics (their versions say they have not changed), for the one edge tried at a time (40 bytes
// a record instead of 64: at 10 M faces the records were the largest array of the collapse).
struct EdgeRecord {
  double cost = 0;
  double quadric_cost = 0;  // dQ / L^2 (or Q(p) / L^2 beside thin faces) at the edge's placement
  double shape = 0;         // Jhat, the dimensionless bending energy, as last computed
  // The versions of the end points (from, to) the placement and quadric cost were computed for.
  std::uint32_t from_version = 0, to_version = 0;
  unsigned char retries = 0;
  char complete = 0;  // 0: cost is a lower bound (quadric part only, or no placement yet)
  // The end the placement was pinned to when computed (pinned_code): a neighbour's collapse can put
  // an end on the boundary without changing its version, and the placement stays the one costed.
  char pinned = 0;
};
static_assert(sizeof(EdgeRecord) == 40);

// A collapse along a patch border drops a border vertex only where the border turns by at most
// 1 degree there: a CAD part's straight edges simplify, its curved ones keep their vertices. A
// 48-gon's rim (7.5 degrees a vertex) lost 4.4 % of its cap's area to chords at 30 %; dropping a
// vertex that turns by 1 degree cuts off a sliver of l^2 sin(1 deg) / 2, under 1 % of l^2.
const double kBorderStraightCosine = std::cos(1.0 * M_PI / 180.0);

class Collapser {
 public:
  Collapser(TriMesh& mesh, const SimplifyParams& params, const CollapseScales& scales, std::vector<Quadric>& quadrics,
            const std::vector<double>& error_cap, std::vector<int>& merged_into, SimplifyResult& result,
            const HeightField& field)
      : mesh_(mesh), params_(params), scales_(scales), quadrics_(quadrics), error_cap_(error_cap),
        merged_into_(merged_into), result_(result), field_(field), patches_(mesh),
        edges_(mesh.n_edges()),
        distance_placements_(params.cost == CollapseCost::Distance ? mesh.n_edges() : 0),
        locked_(mesh.n_vertices(), 0),
        version_(mesh.n_vertices()),
        whole_error_(mesh.n_vertices(), 0),
        min_angle_cosine_(params.min_angle_deg > 0 ? std::cos(params.min_angle_deg * M_PI / 180.0) : 2.0) {
    for (const VertexHandle v : mesh_.vertices()) {
      version_[idx(v)] = next_version_++;
      // A patch border's corner (where three patches meet, or a border meets the boundary) stays.
      const int borders = border_edges(v);
      locked_[idx(v)] = !mesh_.is_manifold(v) || (borders != 0 && (borders != 2 || mesh_.is_boundary(v)));
      whole_error_[idx(v)] = mesh_.is_boundary(v);
    }
    for (const auto f : mesh_.faces()) {
      const HalfedgeHandle h = mesh_.halfedge_handle(f);
      const VertexHandle corners[3] = {mesh_.from_vertex_handle(h), mesh_.to_vertex_handle(h),
                                       mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h))};
      if (smallest_angle_cosine(point(corners[0]), point(corners[1]), point(corners[2])) > kThinFaceCosine)
        for (const VertexHandle w : corners) whole_error_[idx(w)] = 1;
    }
  }

  // Runs the queue. Each time the face count halves (closed meshes only: on the Jacksboro terrain
  // the relaxed interior led later collapses to fold 3 of 4,000 border faces past vertical), and
  // where the queue runs dry before the target, `reshape` may reshape the mesh (relaxation, and
  // when stuck flips too, free collapses the shape guard refused); the queue then starts again.
  void run(std::size_t target, const ReshapeCallback& reshape) {
    faces_before_ = faces_ = mesh_.n_faces();
    result_.banded_queue = banded_;
    to_remove_ = faces_ > target ? faces_ - target : 0;
    reshape_at_ = reshape && closed() ? faces_ / 2 : 0;
    for (int restart = 0;;) {
      const std::size_t collapses_before = result_.collapses;
      run_queue(target);
      if (faces_ > target && faces_ <= reshape_at_) {
        reshape_at_ /= 2;
        result_.reshapes += reshaped(reshape, Reshape::Relax) ? 1 : 0;
        continue;
      }
      if (faces_ <= target || !reshape || restart == kMaxStuckRestarts) return;
      if (restart > 0 && result_.collapses == collapses_before) return;
      if (!reshaped(reshape, Reshape::FlipAndRelax)) return;
      ++result_.stuck_restarts;
      ++restart;
    }
  }

 private:
  enum class Outcome { Collapsed, Topology, Shape, Error };

  double queue_key(double cost, int edge) const { return banded_ ? banded_order_.key(cost, edge) : cost; }

  // Calls `reshape`; the vertices it moved get new versions.
  bool reshaped(const ReshapeCallback& reshape, Reshape how) {
    const auto before = mesh_.points();  // (a copy: cheap next to a relaxation sweep)
    const std::vector<OpenMesh::Vec3d> points_before(before, before + mesh_.n_vertices());
    const bool changed = reshape(how);
    for (const VertexHandle v : mesh_.vertices())
      if (mesh_.point(v) != points_before[idx(v)]) version_[idx(v)] = next_version_++;
    return changed;
  }

  // The greedy order: always the cheapest edge next. (The paper's passes of independent sets were
  // measured slower and no better overall; docs/simplification.md.)
  void run_queue(std::size_t target) {
    for (const EdgeHandle e : mesh_.edges())
      if (!mesh_.status(e).deleted()) push(e);
    while (faces_ > target && faces_ > reshape_at_ && !heap_.empty()) {
      const int edge = heap_.front();
      const EdgeHandle e(edge);
      const std::size_t i = idx(e);
      EdgeRecord& record = edges_[i];
      if (!record.complete) {
        record.cost = complete_cost(e);
        record.complete = 1;
        heap_.set(edge, queue_key(record.cost, edge));
        if (heap_.front() != edge) continue;
      }
      switch (try_collapse(e)) {
        case Outcome::Collapsed:
          requeue_around(last_kept_);
          break;
        case Outcome::Shape:
          if (record.retries++ < kMaxRetries) {
            record.cost = record.cost * kRetryPenalty + std::numeric_limits<double>::min();
            heap_.set(edge, queue_key(record.cost, edge));
          } else {
            heap_.pop_front();
          }
          break;
        default:
          heap_.pop_front();  // back in the queue when its neighbourhood changes
      }
    }
  }

  // After a collapse onto v: v's edges are re-costed (their cost changed); the edges of its link
  // (opposite v in its faces) keep their cost, but one of their faces changed, so those the guards
  // had refused are tried again (bunny00 to 2,000 faces: RMS distance 8.3e-4 -> 7.3e-4). Not
  // beside the boundary: there, on the Jacksboro terrain, they made 6 of 4,000 border faces
  // turn past vertical (each collapse within the 90-degree guard, the sum not).
  // The edges' records and heap slots are scattered over memory (at 1.2 M faces, far beyond the
  // cache): they are all requested first, so that the misses overlap instead of queueing.
  void requeue_around(VertexHandle v) {
    around_.clear();
    links_.clear();
    for (const HalfedgeHandle out : mesh_.voh_range(v)) {
      around_.push_back(mesh_.edge_handle(out));
      if (mesh_.is_boundary(out)) continue;
      const HalfedgeHandle link = mesh_.next_halfedge_handle(out);
      if (mesh_.is_boundary(mesh_.from_vertex_handle(link)) || mesh_.is_boundary(mesh_.to_vertex_handle(link))) continue;
      links_.push_back(mesh_.edge_handle(link));
    }
    for (const std::vector<EdgeHandle>* edges : {&around_, &links_})
      for (const EdgeHandle e : *edges) {
        __builtin_prefetch(&edges_[idx(e)]);
        heap_.prefetch(e.idx());
      }
    for (const EdgeHandle e : around_) push(e);
    for (const EdgeHandle e : links_)
      if (!heap_.contains(e.idx())) push(e);
  }

  // The guards, then the collapse of edge e onto its placement (last_kept_ is the vertex that stays).
  Outcome try_collapse(EdgeHandle e) {
    const HalfedgeHandle h = collapse_direction(e);
    if (!h.is_valid()) {
      ++result_.rejected_topology;
      return Outcome::Topology;
    }
    const VertexHandle removed = mesh_.from_vertex_handle(h), kept = mesh_.to_vertex_handle(h);
    Quadric merged = quadrics_[idx(kept)];
    merged += quadrics_[idx(removed)];
    const Vec3 p = params_.cost == CollapseCost::Distance ? distance_placements_[idx(e)]
                                                          : quadric_placement(e, merged, edges_[idx(e)].pinned);
    if (!collapse_keeps_shape(mesh_, h, p, min_angle_cosine_, field_)) {
      ++result_.rejected_shape;
      return Outcome::Shape;
    }
    double limit = std::min(error_cap_[idx(kept)], error_cap_[idx(removed)]);
    if (params_.max_error > 0) limit = std::min(limit, params_.max_error * scales_.diagonal);
    if (rms_plane_distance(merged, p) > limit) {
      ++result_.rejected_error;
      return Outcome::Error;
    }
    faces_ -= mesh_.is_boundary(e) ? 1 : 2;
    quadrics_[idx(kept)] = merged;
    // The collapse deletes three of the edges around the two end points (the edge and one of
    // each pair it merges): those leave the queue; the others are re-costed around `kept`.
    touched_.clear();
    for (const VertexHandle end : {removed, kept})
      for (const EdgeHandle around : mesh_.ve_range(end)) touched_.push_back(around);
    mesh_.collapse(h);
    mesh_.set_point(kept, to_openmesh(p));
    version_[idx(kept)] = next_version_++;
    merged_into_[idx(removed)] = kept.idx();
    whole_error_[idx(kept)] |= whole_error_[idx(removed)];
    ++result_.collapses;
    for (const EdgeHandle around : touched_)
      if (mesh_.status(around).deleted() && heap_.contains(around.idx())) heap_.remove(around.idx());
    last_kept_ = kept;
    if (params_.progress && result_.collapses % 1024 == 0)
      params_.progress(static_cast<double>(faces_before_ - faces_) / static_cast<double>(to_remove_));
    return Outcome::Collapsed;
  }

  bool closed() const {
    for (const HalfedgeHandle h : mesh_.halfedges())
      if (mesh_.is_boundary(h)) return false;
    return true;
  }

  template <class Handle>
  static std::size_t idx(Handle h) {
    return static_cast<std::size_t>(h.idx());
  }
  Vec3 point(VertexHandle v) const { return to_eigen(mesh_.point(v)); }

  // The patch borders at v (mesh_patches.h).
  int border_edges(VertexHandle v) const {
    int borders = 0;
    for (const auto e : mesh_.ve_range(v)) borders += patches_.border(e);
    return borders;
  }

  // Whether the patch border runs straight on through v (its two border edges turn by at most
  // kBorderTurnDeg): only there may a collapse along the border drop v.
  bool border_straight_at(VertexHandle v) const {
    Vec3 sides[2];
    int found = 0;
    for (const HalfedgeHandle out : mesh_.voh_range(v))
      if (patches_.border(mesh_.edge_handle(out)) && found < 2) sides[found++] = point(mesh_.to_vertex_handle(out)) - point(v);
    return found == 2 && sides[0].dot(sides[1]) <= -kBorderStraightCosine * sides[0].norm() * sides[1].norm();
  }

  // The end point that must stay: a boundary vertex collapsing with an interior one keeps its
  // place; so does a vertex on a patch border, and along a border the end that is not dropped
  // (border_straight_at): the border loses a vertex where it runs straight, and never moves, so
  // each face keeps its side of it.
  VertexHandle pinned_end(VertexHandle a, VertexHandle b) const {
    const bool boundary_a = mesh_.is_boundary(a), boundary_b = mesh_.is_boundary(b);
    if (boundary_a != boundary_b) return boundary_a ? a : b;
    if (!patches_.present()) return VertexHandle();
    const bool border_a = border_edges(a) > 0, border_b = border_edges(b) > 0;
    if (border_a != border_b) return border_a ? a : b;
    if (border_a) return border_straight_at(a) ? b : a;
    return VertexHandle();
  }

  // Whether collapsing a-b keeps every patch border: an edge between two border vertices may
  // collapse only if it is a border edge itself (else the patch between would be pinched) and
  // the border runs straight through one of its ends.
  bool keeps_patch_borders(EdgeHandle e, VertexHandle a, VertexHandle b) const {
    if (!patches_.present() || border_edges(a) == 0 || border_edges(b) == 0) return true;
    return patches_.border(e) && (border_straight_at(a) || border_straight_at(b));
  }

  // Queue the edge with an estimate of its cost: Bending's quadric part (cheap, exact) with the
  // edge's last known bending energy (0 before the first evaluation); Distance's exact cost. The
  // edge is completed when it reaches the front (a fresh energy, or Distance's placement) and goes
  // back into the queue if it is no longer the cheapest: J is only computed for edges near the
  // front, which halves the evaluations.
  void push(EdgeHandle e) {
    if (prepare(e)) heap_.set(e.idx(), queue_key(edges_[idx(e)].cost, e.idx()));
  }

  // The placement and the cost estimate of edge e (in its record); false if it may never collapse.
  bool prepare(EdgeHandle e) {
    const std::size_t i = idx(e);
    EdgeRecord& record = edges_[i];
    record.retries = 0;
    record.complete = 0;
    const HalfedgeHandle h = mesh_.halfedge_handle(e, 0);
    const VertexHandle a = mesh_.from_vertex_handle(h), b = mesh_.to_vertex_handle(h);
    if (locked_[idx(a)] || locked_[idx(b)] || !keeps_patch_borders(e, a, b)) return false;
    const Vec3 pa = point(a), pb = point(b);
    const double length = (pb - pa).norm();
    if (params_.cost == CollapseCost::Distance) {
      record.cost = length / scales_.edge_length;
      return true;
    }
    // Neither end point has moved or merged since the placement was computed (the edge is queued
    // again beside a collapse, or after a reshape): it still holds. A version is never reused, so
    // this also tells an edge a flip has turned.
    if (record.from_version == version_[idx(a)] && record.to_version == version_[idx(b)]) {
      record.cost = bending_cost(record, length);
      return true;
    }
    record.from_version = version_[idx(a)];
    record.to_version = version_[idx(b)];
    Quadric q = quadrics_[idx(a)];
    q += quadrics_[idx(b)];
    record.pinned = pinned_code(a, b);
    const Vec3 p = quadric_placement(e, q, record.pinned);
    double error = evaluate(q, p);
    if (!whole_error_[idx(a)] && !whole_error_[idx(b)])
      error = std::max(0.0, error - evaluate(quadrics_[idx(a)], pa) - evaluate(quadrics_[idx(b)], pb));
    record.quadric_cost = error / (scales_.edge_length * scales_.edge_length);
    record.cost = bending_cost(record, length);
    return true;
  }

  // pinned_end(a, b) of halfedge 0's ends a -> b: 0 neither, 1 a, 2 b.
  char pinned_code(VertexHandle a, VertexHandle b) const {
    const VertexHandle pinned = pinned_end(a, b);
    return !pinned.is_valid() ? 0 : pinned == a ? 1 : 2;
  }

  // Where edge e collapses to under the cost of Bending, `q` the sum of its end points' quadrics:
  // the pinned end (pinned_code), else the quadric's minimiser near the midpoint, else (too far)
  // the best of the midpoint and the end points. (Floating-point sums commute: the sum in either
  // order is the same q.)
  Vec3 quadric_placement(EdgeHandle e, const Quadric& q, char pinned) const {
    const HalfedgeHandle h = mesh_.halfedge_handle(e, 0);
    const VertexHandle a = mesh_.from_vertex_handle(h), b = mesh_.to_vertex_handle(h);
    if (pinned) return point(pinned == 1 ? a : b);
    const Vec3 pa = point(a), pb = point(b);
    const Vec3 middle = 0.5 * (pa + pb);
    Vec3 p = minimiser_near(q, middle);
    if (!((p - middle).norm() <= kFarPlacement * (pb - pa).norm())) {
      p = middle;
      for (const Vec3& end : {pa, pb})
        if (evaluate(q, end) < evaluate(q, p)) p = end;
    }
    return p;
  }

  // Bending: the lower bound times the bending-energy shape factor. Distance: the placement.
  double complete_cost(EdgeHandle e) {
    const HalfedgeHandle h = mesh_.halfedge_handle(e, 0);
    const VertexHandle a = mesh_.from_vertex_handle(h), b = mesh_.to_vertex_handle(h);
    const double length = (point(b) - point(a)).norm();
    EdgeRecord& record = edges_[idx(e)];
    ++result_.energy_evaluations;
    if (params_.cost == CollapseCost::Distance) {
      distance_placements_[idx(e)] = distance_placement(a, b, length);
      return record.cost;
    }
    const EdgeEnergy energy = edge_energy(rings_, a, b, nullptr);
    record.shape = std::isfinite(energy.energy) && length > 0 ? (energy.energy / length) / scales_.energy_per_length : 0.0;
    return bending_cost(record, length);
  }

  // dQ (1 + mu Jhat) + eps Jhat (|e| / L)^2, with the edge's last known Jhat until it is recomputed.
  double bending_cost(const EdgeRecord& record, double length) const {
    const double relative_length = length / scales_.edge_length;
    return record.quadric_cost * (1 + kShapeWeight * record.shape) +
           kShapeTieBreak * record.shape * relative_length * relative_length;
  }

  // The paper's placement: the sliding-landmark point on the edge, then the local RBF height map.
  Vec3 distance_placement(VertexHandle a, VertexHandle b, double length) {
    const VertexHandle pinned = pinned_end(a, b);
    if (pinned.is_valid()) return point(pinned);
    if (mesh_.is_boundary(a) && mesh_.is_boundary(b)) {
      // Along the boundary: the end point the boundary constraint planes prefer (a corner stays).
      Quadric q = quadrics_[idx(a)];
      q += quadrics_[idx(b)];
      return evaluate(q, point(a)) <= evaluate(q, point(b)) ? point(a) : point(b);
    }
    const EdgeEnergy energy = edge_energy(rings_, a, b, &neighbourhood_);
    if (!std::isfinite(energy.energy)) return 0.5 * (point(a) + point(b));
    try {
      const Vec3 projected = project_to_local_surface(neighbourhood_, energy.point);
      if ((projected - energy.point).norm() < 0.5 * length) return projected;
    } catch (const Error&) {
    }
    return energy.point;
  }

  // The halfedge to collapse (from the removed vertex to the kept one), invalid if the link
  // condition fails (it is the same in both directions) or a boundary vertex would leave the boundary.
  HalfedgeHandle collapse_direction(EdgeHandle e) {
    const HalfedgeHandle h0 = mesh_.halfedge_handle(e, 0), h1 = mesh_.halfedge_handle(e, 1);
    const VertexHandle a = mesh_.from_vertex_handle(h0), b = mesh_.to_vertex_handle(h0);
    if (locked_[idx(a)] || locked_[idx(b)] || !keeps_patch_borders(e, a, b)) return HalfedgeHandle();
    const HalfedgeHandle h = pinned_end(a, b) == a ? h1 : h0;  // a pinned boundary vertex stays
    return link_.holds(h) ? h : HalfedgeHandle();
  }

  TriMesh& mesh_;
  const SimplifyParams& params_;
  const CollapseScales& scales_;
  std::vector<Quadric>& quadrics_;
  const std::vector<double>& error_cap_;
  std::vector<int>& merged_into_;
  SimplifyResult& result_;
  const HeightField field_;
  const FacePatches patches_;
  std::vector<EdgeRecord> edges_;
  std::vector<Vec3> distance_placements_;  // per edge, for CollapseCost::Distance only (its RBF placement costs)
  std::vector<char> locked_;  // non-manifold vertices: never moved
  // Changes each time a vertex moves or merges (unique over all vertices and times: never 0).
  std::vector<std::uint32_t> version_;
  std::uint32_t next_version_ = 1;
  std::vector<char> whole_error_;  // costed by Q(p): on the boundary, or standing for a thin face's corner
  double min_angle_cosine_;
  IndexedHeap heap_{mesh_.n_edges()};
  const bool banded_ = mesh_.n_edges() >= params_.banded_queue_from_edges;
  const BandedOrder banded_order_{mesh_.n_edges(), kCostBand, kBlockShift};
  std::vector<Vec3> neighbourhood_;
  std::vector<EdgeHandle> touched_, around_, links_;
  VertexHandle last_kept_;
  std::size_t reshape_at_ = 0;  // face count of the next relaxation
  std::size_t faces_before_ = 0, faces_ = 0, to_remove_ = 0;
  RingUnion rings_{mesh_};
  LinkCondition link_{mesh_};
};

}  // namespace

void collapse_edges(TriMesh& mesh, std::size_t target, const SimplifyParams& params, const CollapseScales& scales,
                    std::vector<Quadric>& quadrics, const std::vector<double>& error_cap,
                    std::vector<int>& merged_into, SimplifyResult& result, const HeightField& field,
                    const ReshapeCallback& reshape) {
  Collapser(mesh, params, scales, quadrics, error_cap, merged_into, result, field).run(target, reshape);
}

}  // namespace meshprep::detail
