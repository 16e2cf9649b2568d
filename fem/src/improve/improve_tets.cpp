// The schedule of tet improvement (improve_tets.h): the tets below the goal, worst first, each
// given the best topological move around it, else smoothing of its free corners, else a new
// vertex; passes until the goal is reached or a pass gains nothing.
#include "meshprep/fem/improve_tets.h"

#include "boundary_slides.h"
#include "compound_move.h"
#include "edge_contraction.h"
#include "flat_boundary_tets.h"
#include "surface_limits.h"
#include "tet_objective.h"
#include "tet_complex.h"
#include "topological_moves.h"
#include "vertex_insertion.h"
#include "vertex_smoothing.h"

#include "meshprep/core/errors.h"
#include "meshprep/fem/fem_parameters.h"
#include "meshprep/core/origin_shift.h"
#include "meshprep/fem/tet_quality.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <optional>
#include <cmath>
#include <queue>
#include <unordered_map>
#include <cstdio>
#include <cstdlib>

namespace meshprep {
namespace {

using namespace improve;
using Clock = std::chrono::steady_clock;

constexpr double kRadiansPerDegree = M_PI / 180.0;
// Rings of more tets than this are not removed: the programme is cubic in the ring, and Klingner
// & Shewchuk found larger rings rarely help.
constexpr std::size_t kMaxRing = 10;
// Multi-face removal looks at most this many sandwiched faces.
constexpr std::size_t kMaxSandwichedFaces = 12;
// Vertex insertion grows its cavity to at most this many tets.
constexpr std::size_t kMaxCavity = 24;
// When stuck, the tets near the stuck ones are worked on towards a goal this many degrees higher
// (twice as high the second time), then the goal is tried again.
constexpr int kEscalations = 2;
constexpr double kEscalationDeg = 5;
constexpr std::size_t kEscalatedPasses = 2;
constexpr int kEscalationRings = 2;  // the stuck tets' corners, their neighbours and theirs
// Compound moves try the best few candidates of the topological moves (each costs a smoothing).
constexpr std::size_t kCompoundCandidates = 2;
// A pass tries at most this many tets per tet below the goal at its start, and no more than per
// tet below the goal when the run began: moves that each gain a little can feed one another for
// long (every smoothing step raises a minimum by kMinSineGain, but neighbours trade such gains);
// the next pass starts from the queue afresh. Where the count grows (tets crowding a knife edge of
// the surface), the run's own start bounds the work.
constexpr std::size_t kTriesPerBadTet = 20;
// How often (in tets tried) the run asks the cancellation callback and reports progress.
constexpr std::size_t kPollEvery = 256;
constexpr std::size_t kListedLimitingEdges = 100;


struct DihedralRange {
  double min = 180, max = 0;
};

DihedralRange dihedral_range(const TetMesh& mesh, const std::function<bool()>& cancelled) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, mesh.tets.size(), 4096), DihedralRange{},
      [&](const auto& range, DihedralRange r) {
        if (cancelled && cancelled()) throw Cancelled("tet improvement stopped");
        for (std::size_t t = range.begin(); t != range.end(); ++t) {
          const auto& v = mesh.tets[t];
          const TetShape s = tet_shape(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.points[v[3]]);
          r.min = std::min(r.min, s.min_dihedral_deg);
          r.max = std::max(r.max, s.max_dihedral_deg);
        }
        return r;
      },
      [](DihedralRange a, const DihedralRange& b) { return DihedralRange{std::min(a.min, b.min), std::max(a.max, b.max)}; });
}

class Schedule {
 public:
  // The run ends by `end` (none: no time limit); `began` is when the improvement began, for the
  // progress the clock gives.
  Schedule(TetComplex& mesh, const BoundarySlides* slides, const ImproveParams& params, ImproveResult& result,
           Clock::time_point began, std::optional<Clock::time_point> end)
      : mesh_(mesh),
        slides_(slides),
        params_(params),
        result_(result),
        goal_(std::sin(params.goal_min_dihedral_deg * kRadiansPerDegree)),
        work_goal_(goal_),
        began_(began),
        end_(end) {}

  std::size_t below_goal() const {
    std::size_t n = 0;
    for (TetId t = 0; t < mesh_.tet_slots(); ++t) n += mesh_.alive(t) && mesh_.quality(t) < goal_;
    return n;
  }

  double worst() const {
    double w = 1;
    for (TetId t = 0; t < mesh_.tet_slots(); ++t)
      if (mesh_.alive(t)) w = std::min(w, mesh_.quality(t));
    return w;
  }

  void run() {
    result_.below_goal_before = below_goal();
    if (result_.below_goal_before == 0) {
      result_.stopped_by = "nothing to do";
      return;
    }
    result_.stopped_by = run_passes();
    for (int round = 1; round <= kEscalations && result_.stopped_by == "no gain"; ++round) {
      // Stuck: work on the stuck tets' surroundings towards a higher goal, which may free room the
      // hill climbing at the goal cannot find, then go back to the goal. The detour may also end
      // in a worse local optimum: then the mesh is taken back to where it was.
      const TetComplex before_detour = mesh_;
      const ImproveResult result_before = result_;
      const std::size_t below = below_goal();
      const double worst_before = worst();
      escalate(kEscalationDeg * round);
      run_passes(kEscalatedPasses);
      deescalate();
      const std::string stopped_by = run_passes();
      const double worst_after = worst();
      if (worst_after < worst_before || (worst_after == worst_before && below_goal() >= below)) {
        const std::size_t passes = result_.passes;
        const std::size_t below_after = below_goal();
        mesh_ = before_detour;
        result_ = result_before;
        result_.passes = passes;
        result_.taken_back.push_back(
            {"improve", "no gain", "detour", 1,
             "working towards a goal " + std::to_string(static_cast<int>(kEscalationDeg * round)) +
                 " deg higher around the stuck tets ended no better; the tets before it are kept",
             {{"tets_below_goal", static_cast<double>(below_after)}, {"worst_quality", worst_after}},
             {{"tets_below_goal", static_cast<double>(below)}, {"worst_quality", worst_before}}});
        failed_.clear();
        if (stopped_by == "time limit") result_.stopped_by = stopped_by;  // the time ended the detour
        return;
      }
      result_.stopped_by = stopped_by;
    }
  }


 private:
  // Passes until the goal is reached, a pass gains nothing, or the limits: the reason.
  std::string run_passes(std::size_t at_most = ~std::size_t(0)) {
    std::size_t below = below_goal();
    double worst_now = worst();
    for (std::size_t pass = 0; pass < at_most && result_.passes < params_.max_passes; ++pass) {
      if (!may_go_on()) return "time limit";
      ++result_.passes;
      if (!run_pass()) return "time limit";
      const std::size_t below_after = below_goal();
      const double worst_after = worst();
      if (below_after == 0) return "goal reached";
      // A pass that only nudges the worst tet while the count below the goal does not fall is
      // stuck at what the surface allows (elk's 1.2 degree knife edge: the worst sine rose by
      // 7e-5 in four passes while the count grew from 578 to 3,776, and each pass took longer).
      if (below_after >= below && worst_after < worst_now + kMinSineGain) return "no gain";
      below = below_after;
      worst_now = worst_after;
    }
    return "pass limit";
  }

  // Queue threshold raised by `degrees`, only for tets near the ones still below the goal.
  void escalate(double degrees) {
    near_.assign(mesh_.points(), 0);
    for (TetId t = 0; t < mesh_.tet_slots(); ++t)
      if (mesh_.alive(t) && mesh_.quality(t) < goal_)
        for (const VertexId v : mesh_.tet(t)) near_[v] = 1;
    for (int ring = 0; ring < kEscalationRings; ++ring) {
      std::vector<std::uint8_t> grown = near_;
      for (TetId t = 0; t < mesh_.tet_slots(); ++t) {
        if (!mesh_.alive(t)) continue;
        const Tetrahedron& c = mesh_.tet(t);
        if (near_[c[0]] || near_[c[1]] || near_[c[2]] || near_[c[3]])
          for (const VertexId v : c) grown[v] = 1;
      }
      near_ = std::move(grown);
    }
    work_goal_ = std::sin(std::min(59.0, params_.goal_min_dihedral_deg + degrees) * kRadiansPerDegree);
    failed_.clear();
  }

  void deescalate() {
    near_.clear();
    work_goal_ = goal_;
    failed_.clear();
  }

  // A queued tet, stale once its slot holds another tet or the tet changed shape.
  struct Entry {
    double quality;
    TetId tet;
    Tetrahedron corners;
    bool operator>(const Entry& o) const { return quality != o.quality ? quality > o.quality : tet > o.tet; }
  };
  using Queue = std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>>;

  void push_if_bad(TetId t) {
    if (!mesh_.alive(t) || !(mesh_.quality(t) < work_goal_)) return;
    const Tetrahedron& c = mesh_.tet(t);
    if (!near_.empty() && !((c[0] < near_.size() && near_[c[0]]) || (c[1] < near_.size() && near_[c[1]]) ||
                            (c[2] < near_.size() && near_[c[2]]) || (c[3] < near_.size() && near_[c[3]])))
      return;
    queue_.push({mesh_.quality(t), t, c});
  }

  // Asks the cancellation callback and the clock; false when the time is up.
  bool may_go_on() const {
    if (params_.cancelled && params_.cancelled()) throw Cancelled("tet improvement stopped");
    return !(end_ && Clock::now() >= *end_);
  }

  // The progress: the share of this pass's queue done, or of the time limit spent if more (a run
  // that ends at its time limit still moves its bar).
  double progress(double queue_done) const {
    double time_spent = 0;
    if (end_)
      time_spent = std::chrono::duration<double>(Clock::now() - began_).count() /
                   std::max(1e-9, std::chrono::duration<double>(*end_ - began_).count());
    return std::clamp(std::max(queue_done, time_spent), 0.0, 1.0);
  }

  // One pass over the tets below the goal, worst first; false if the time limit stopped it.
  bool run_pass() {
    queue_ = Queue();
    for (TetId t = 0; t < mesh_.tet_slots(); ++t) push_if_bad(t);
    const double initial = static_cast<double>(std::max<std::size_t>(1, result_.below_goal_before));
    // Escalated, the queue holds good tets near the stuck ones: the budget follows the stuck ones.
    const std::size_t budget =
        kTriesPerBadTet * std::min(near_.empty() ? queue_.size() : below_goal(), result_.below_goal_before);
    std::size_t tried = 0;
    while (!queue_.empty() && tried < budget) {
      const Entry e = queue_.top();
      queue_.pop();
      if (!mesh_.alive(e.tet) || mesh_.tet(e.tet) != e.corners || mesh_.quality(e.tet) != e.quality) continue;
      if (++tried % kPollEvery == 0) {
        if (!may_go_on()) return false;
        if (params_.progress) params_.progress(progress(1.0 - static_cast<double>(queue_.size()) / initial));
      }
      if (unchanged_since_failure(e.tet)) continue;
      if (!improve_tet(e.tet)) failed_[sorted(e.corners)] = epoch_;
    }
    return true;
  }

  // Tries to raise tet t; the tets a kept move changed are queued if still below the goal.
  bool improve_tet(TetId t) {
    candidates_.clear();
    if (params_.topological_moves && try_topological(t)) return true;
    if (params_.smoothing && try_smoothing(t)) return true;
    if (params_.topological_moves && try_contraction(t)) return true;
    if (params_.topological_moves && params_.smoothing && try_compound()) return true;
    if (params_.insertion && insert_vertex(mesh_, t, kMaxCavity)) {
      ++result_.inserted_vertices;
      changed(mesh_.created());
      changed_star(static_cast<VertexId>(mesh_.points() - 1));
      return true;
    }
    return false;
  }

  // The best improving move around t; every candidate is kept for try_compound.
  bool try_topological(TetId t) {
    const Tetrahedron tet = mesh_.tet(t);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) candidates_.push_back({edge_removal(mesh_, t, tet[i], tet[j], kMaxRing), true});
    for (int c = 0; c < 4; ++c) candidates_.push_back({multi_face_removal(mesh_, t, c, kMaxSandwichedFaces), false});
    candidates_.erase(std::remove_if(candidates_.begin(), candidates_.end(), [](const Candidate& c) { return c.move.fresh.empty(); }),
                      candidates_.end());
    std::sort(candidates_.begin(), candidates_.end(),
              [](const Candidate& a, const Candidate& b) { return a.move.new_worst > b.move.new_worst; });
    if (candidates_.empty() || !candidates_.front().move.improves()) return false;
    const Candidate& best = candidates_.front();
    if (!mesh_.replace(best.move.old, best.move.fresh)) return false;
    ++(best.edge ? result_.edge_removals : result_.multi_face_removals);
    changed(mesh_.created());
    return true;
  }

  bool try_smoothing(TetId t) {
    bool moved = false;
    const Tetrahedron tet = mesh_.tet(t);
    for (const VertexId v : tet) {
      if (mesh_.free_vertex(v)) {
        if (!smooth_vertex(mesh_, v)) continue;
        ++result_.vertex_moves;
      } else {
        if (!slides_ || !slides_->may_slide(v) || !slides_->slide(mesh_, v)) continue;
        ++result_.boundary_vertex_moves;
      }
      moved = true;
      changed_star(v);
    }
    return moved;
  }

  // The best improving contraction of a free corner of t.
  bool try_contraction(TetId t) {
    Move best;
    VertexId removed = kNoVertex;
    for (const VertexId v : mesh_.tet(t)) {
      if (!mesh_.free_vertex(v)) continue;
      Move m = best_contraction(mesh_, v);
      if (m.improves() && (best.fresh.empty() || m.new_worst > best.new_worst)) best = std::move(m), removed = v;
    }
    if (removed == kNoVertex || !mesh_.remove_vertex(removed, best.old, best.fresh)) return false;
    ++result_.contractions;
    changed(mesh_.created());
    return true;
  }

  // The candidates no move kept alone, best first, each followed by smoothing (compound_move.h).
  // Candidates are valid only while the mesh is as try_topological saw it: smoothing had failed.
  bool try_compound() {
    std::vector<TetId> tets;
    for (std::size_t k = 0; k < candidates_.size() && k < kCompoundCandidates; ++k) {
      const Candidate& c = candidates_[k];
      if (!move_and_smooth(mesh_, c.move, tets)) continue;
      ++(c.edge ? result_.edge_removals : result_.multi_face_removals);
      ++result_.compound_moves;
      changed(tets);
      return true;
    }
    return false;
  }

  // Tets changed shape or were made: they are queued if below the goal, and their corners are
  // stamped with a new epoch, so that the tets around them that failed before are tried again.
  void changed(const std::vector<TetId>& tets) {
    ++epoch_;
    vertex_epoch_.resize(mesh_.points(), 0);
    for (const TetId t : tets) {
      push_if_bad(t);
      for (const VertexId v : mesh_.tet(t)) vertex_epoch_[v] = epoch_;
    }
  }

  void changed_star(VertexId v) {
    mesh_.star(v, star_);
    changed(star_);
  }

  // A tet that failed every move is not tried again until a move touches one of its corners.
  bool unchanged_since_failure(TetId t) const {
    const auto found = failed_.find(sorted(mesh_.tet(t)));
    if (found == failed_.end()) return false;
    for (const VertexId v : mesh_.tet(t))
      if (v < vertex_epoch_.size() && vertex_epoch_[v] > found->second) return false;
    return true;
  }

  static Tetrahedron sorted(Tetrahedron t) {
    std::sort(t.begin(), t.end());
    return t;
  }
  struct TetHash {
    std::size_t operator()(const Tetrahedron& t) const {
      std::uint64_t h = 0;
      for (const VertexId v : t) h = (h ^ v) * 0x9E3779B97F4A7C15ull;
      return static_cast<std::size_t>(h ^ (h >> 29));
    }
  };

  TetComplex& mesh_;
  const BoundarySlides* slides_;  // null: the boundary is kept exactly
  const ImproveParams& params_;
  ImproveResult& result_;
  const double goal_;  // the objective's value at the goal angles
  double work_goal_;   // the queue's threshold: the goal, or higher while escalated
  std::vector<std::uint8_t> near_;  // while escalated: the vertices near the stuck tets
  struct Candidate {
    Move move;
    bool edge;  // edge removal, else multi-face removal
  };
  std::vector<Candidate> candidates_;
  std::vector<TetId> star_;
  Queue queue_;
  std::uint64_t epoch_ = 0;                  // successful moves so far
  std::vector<std::uint64_t> vertex_epoch_;  // the last move that changed a tet of the vertex
  std::unordered_map<Tetrahedron, std::uint64_t, TetHash> failed_;  // sorted corners -> epoch
  Clock::time_point began_;
  std::optional<Clock::time_point> end_;
};

}  // namespace

void check_improve_params(const ImproveParams& p) {
  const ImproveParameters& info = improve_parameters();
  check_parameter("improve", info.goal_min_dihedral_deg, p.goal_min_dihedral_deg);
  check_parameter("improve", info.goal_max_dihedral_deg, p.goal_max_dihedral_deg);
  check_parameter("improve", info.max_passes, static_cast<double>(p.max_passes));
  if (p.boundary_deviation) check_parameter("improve", info.boundary_deviation, *p.boundary_deviation);
  if (!(p.time_limit_seconds == kAutomaticTimeLimit || (p.time_limit_seconds >= 0 && std::isfinite(p.time_limit_seconds))))
    throw InvalidInput("improve: time_limit_seconds must be -1 (automatic), 0 (none) or a positive number of seconds, not " +
                       parameter_text(p.time_limit_seconds));
}

const std::vector<TetQualityPreset>& tet_quality_presets() {
  static const std::vector<TetQualityPreset> presets = {
      {"default", ImproveParams().goal_min_dihedral_deg, ImproveParams().goal_max_dihedral_deg}, {"high", 20, 150}};
  return presets;
}

std::string tet_quality_of(const ImproveParams& params) {
  for (const TetQualityPreset& p : tet_quality_presets())
    if (p.goal_min_dihedral_deg == params.goal_min_dihedral_deg && p.goal_max_dihedral_deg == params.goal_max_dihedral_deg)
      return p.name;
  return "custom";
}

void apply_tet_quality(ImproveParams& params, const std::string& name) {
  if (name == "custom") return;
  for (const TetQualityPreset& p : tet_quality_presets())
    if (name == p.name) {
      params.goal_min_dihedral_deg = p.goal_min_dihedral_deg;
      params.goal_max_dihedral_deg = p.goal_max_dihedral_deg;
      return;
    }
  throw InvalidInput("improve: tet_quality must be default, high or custom, not '" + name + "'");
}

double automatic_improve_time_limit(std::size_t tets) {
  return kAutomaticTimeLimitScale *
         (kAutomaticTimeLimitFloorSeconds + kAutomaticTimeLimitPerTetSeconds * static_cast<double>(tets));
}

namespace {

// A goal past the default's: the climb from the default's result may take this many times the
// first stage's time, and at least this long.
constexpr double kClimbShareOfFloor = 2;
constexpr double kClimbFloorSeconds = 1;

// The improvement's own time limit on `tets` tets: the one set, or the automatic one (0: none).
double own_time_limit(const ImproveParams& params, std::size_t tets) {
  return params.time_limit_seconds == kAutomaticTimeLimit ? automatic_improve_time_limit(tets) : params.time_limit_seconds;
}

// The boundary edges that cap the tets below the goal (surface_limits.h), into `result`; `shift`
// takes the complex's points back to the mesh's.
void list_limiting_edges(const TetComplex& complex, double goal_min_dihedral_deg, const Vec3& shift, ImproveResult& result) {
  std::vector<LimitingBoundaryEdge> limiting = limiting_boundary_edges(complex, goal_min_dihedral_deg);
  for (LimitingBoundaryEdge& e : limiting) e.midpoint += shift;
  result.limiting_edge_count = limiting.size();
  result.surface_bound_deg = limiting.empty() ? goal_min_dihedral_deg : limiting.front().bound_deg;
  if (limiting.size() > kListedLimitingEdges) limiting.resize(kListedLimitingEdges);
  result.limiting_edges = std::move(limiting);
}

// The diagonal of the box around the complex's points.
double bounding_diagonal(const TetComplex& complex) {
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (VertexId v = 0; v < complex.points(); ++v) low = low.cwiseMin(complex.point(v)), high = high.cwiseMax(complex.point(v));
  return complex.points() > 0 ? (high - low).norm() : 0.0;
}

// One run of the schedule at params' goals.
ImproveResult improve_at_goal(TetMesh& mesh, const ImproveParams& params) {
  const Clock::time_point start = Clock::now();
  ImproveResult result;
  check_tet_mesh_structure(mesh);
  // The setup below visits every tet several times (seconds on millions of tets): it asks the
  // cancellation callback per block of tets, and between its steps.
  const auto poll = [&params] {
    if (params.cancelled && params.cancelled()) throw Cancelled("tet improvement stopped");
  };
  const DihedralRange before = dihedral_range(mesh, params.cancelled);
  result.min_dihedral_before_deg = before.min;
  result.max_dihedral_before_deg = before.max;
  result.tets_before = mesh.tets.size();
  // Flat tets on the boundary, which no move below can touch, go first (flat_boundary_tets.h);
  // their rounding may have given them a negative volume, which is no tangle. They go from a copy,
  // the rest works on: a cancelled run leaves `mesh` as it was.
  std::optional<TetMesh> unflattened;
  if (!flat_tets(mesh).empty()) {
    unflattened = mesh;
    while (const std::size_t removed = remove_flat_boundary_tets(*unflattened))
      result.flat_boundary_tets_removed += removed;
  }
  const TetMesh& input = unflattened ? *unflattened : mesh;
  poll();
  // A tet of negative volume folds through its neighbours (the readers turn over mirrored regions
  // only): every move here keeps volumes positive, so none can mend it. Untangling is not offered.
  std::size_t negative = 0;
  for (std::size_t t = 0; t < input.tets.size(); ++t) negative += tet_volume(input, t) < 0;
  if (negative > 0)
    throw InvalidInput("tet mesh: " + std::to_string(negative) +
                       " tets have negative volume among positive ones: the mesh is tangled (tets overlap), which "
                       "the improvement cannot mend");
  const double obtuse_weight = std::sin(params.goal_min_dihedral_deg * kRadiansPerDegree) /
                               std::sin((180.0 - params.goal_max_dihedral_deg) * kRadiansPerDegree);
  // Far from the origin (a part placed at 1e9) the objective's products lose the shape's bits:
  // work next to it. The shift is exact both ways, so unmoved points come back bit for bit.
  const Vec3 shift = origin_shift(input.points);
  TetMesh moved;
  if (!shift.isZero()) {
    moved.points = input.points;
    for (Vec3& p : moved.points) p -= shift;
    moved.tets = input.tets;
    moved.tet_regions = input.tet_regions;
    moved.boundary_faces = input.boundary_faces;
    moved.boundary_tags = input.boundary_tags;
  }
  poll();
  TetComplex complex(shift.isZero() ? input : moved, obtuse_weight, params.cancelled);
  poll();
  list_limiting_edges(complex, params.goal_min_dihedral_deg, shift, result);
  poll();

  // The time limit counts from the start above (the setup too), shortened to the command's deadline.
  const double limit = params.deadline.limit(own_time_limit(params, mesh.tets.size()));
  std::optional<Clock::time_point> end;
  if (limit > 0) end = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limit));
  const double diagonal = bounding_diagonal(complex);
  std::optional<BoundarySlides> slides;
  if (params.boundary_deviation.value_or(0) > 0)
    slides.emplace(complex, shift.isZero() ? input : moved, *params.boundary_deviation * diagonal);
  Schedule schedule(complex, slides ? &*slides : nullptr, params, result, start, end);
  schedule.run();
  result.below_goal_after = schedule.below_goal();
  if (result.boundary_vertex_moves > 0) {
    // The boundary moved: what it allows now.
    double farthest = 0;
    for (VertexId v = 0; v < complex.points(); ++v)
      if (slides->may_slide(v)) farthest = std::max(farthest, slides->displacement(complex, v));
    result.boundary_max_displacement_relative = farthest / diagonal;
    list_limiting_edges(complex, params.goal_min_dihedral_deg, shift, result);
  }
  if (result.passes > 0) {
    mesh = complex.to_mesh(input);
    for (Vec3& p : mesh.points) p += shift;
  } else if (unflattened) {
    mesh = std::move(*unflattened);
  }
  result.tets_after = mesh.tets.size();
  const DihedralRange after = dihedral_range(mesh, {});
  result.min_dihedral_after_deg = after.min;
  result.max_dihedral_after_deg = after.max;
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

// The smallest of sin(smallest dihedral) and w sin(180 - largest), w weighting the obtuse side as
// the objective does at these goals (tet_objective.h): which of two results is the better.
double worst_quality(double min_deg, double max_deg, const ImproveParams& goals) {
  const double w = std::sin(goals.goal_min_dihedral_deg * kRadiansPerDegree) /
                   std::sin((180.0 - goals.goal_max_dihedral_deg) * kRadiansPerDegree);
  return std::min(std::sin(min_deg * kRadiansPerDegree), w * std::sin((180.0 - max_deg) * kRadiansPerDegree));
}

}  // namespace

ImproveResult improve_tets(TetMesh& mesh, const ImproveParams& params) {
  check_improve_params(params);
  // Every move here is a move of linear tets; a second-order mesh is made after the improvement.
  if (mesh.quadratic())
    throw InvalidInput("improve: the mesh is second-order (10-node tets); the improvement works on linear tets: "
                       "improve the linear mesh, then make it second-order (--order 2)");
  const ImproveParams floor_goals;  // the default goals
  const bool past_the_floor = params.goal_min_dihedral_deg > floor_goals.goal_min_dihedral_deg ||
                              params.goal_max_dihedral_deg < floor_goals.goal_max_dihedral_deg;
  if (!past_the_floor) return improve_at_goal(mesh, params);
  // A goal past the default floor is climbed in two stages: the default goals first, then the
  // goal asked from there, on a copy kept only if it ends no worse (a goal of 20 straight from
  // TetGen's tets ended worse than the default's on 9 of the 56 shared meshes, cow 11.9 -> 7.6
  // deg: bench/RESULTS.md "Tets at goal 20/150 today"). Each stage has its own time limit.
  ImproveParams first = params;
  if (params.boundary_deviation) first.boundary_deviation = 0.5 * *params.boundary_deviation;
  first.goal_min_dihedral_deg = floor_goals.goal_min_dihedral_deg;
  first.goal_max_dihedral_deg = floor_goals.goal_max_dihedral_deg;
  if (params.progress) first.progress = [&params](double f) { params.progress(0.5 * f); };
  // Both on copies: a stop in either leaves `mesh` as it was.
  TetMesh floor_mesh = mesh;
  ImproveResult floor = improve_at_goal(floor_mesh, first);
  TetMesh climbed = floor_mesh;
  ImproveParams second = params;
  second.boundary_deviation = first.boundary_deviation;
  // The climb's budget: at most twice the first stage's time (at least kClimbFloorSeconds), within
  // its own limit (none when the user asked for none): the quality mode then costs at most about
  // three default runs of the improvement.
  const double own = own_time_limit(params, floor_mesh.tets.size());
  const double climb = std::max(kClimbShareOfFloor * floor.seconds, kClimbFloorSeconds * kAutomaticTimeLimitScale);
  second.time_limit_seconds = own > 0 ? std::min(own, climb) : 0;  // 0: the user asked for no limit
  if (params.progress) second.progress = [&params](double f) { params.progress(0.5 + 0.5 * f); };
  ImproveResult high = improve_at_goal(climbed, second);
  ImproveResult result = high;
  result.min_dihedral_before_deg = floor.min_dihedral_before_deg;
  result.max_dihedral_before_deg = floor.max_dihedral_before_deg;
  result.tets_before = floor.tets_before;
  result.edge_removals += floor.edge_removals;
  result.multi_face_removals += floor.multi_face_removals;
  result.vertex_moves += floor.vertex_moves;
  result.compound_moves += floor.compound_moves;
  result.contractions += floor.contractions;
  result.inserted_vertices += floor.inserted_vertices;
  result.boundary_vertex_moves += floor.boundary_vertex_moves;
  result.boundary_max_displacement_relative += floor.boundary_max_displacement_relative;
  result.flat_boundary_tets_removed += floor.flat_boundary_tets_removed;
  result.passes += floor.passes;
  result.seconds += floor.seconds;
  result.taken_back.insert(result.taken_back.begin(), floor.taken_back.begin(), floor.taken_back.end());
  const double floor_worst = worst_quality(floor.min_dihedral_after_deg, floor.max_dihedral_after_deg, params);
  const double high_worst = worst_quality(high.min_dihedral_after_deg, high.max_dihedral_after_deg, params);
  if (high_worst >= floor_worst) {
    mesh = std::move(climbed);
    return result;
  }
  mesh = std::move(floor_mesh);
  // Taken back: the tets of the first stage, judged at the goal asked.
  result.taken_back.push_back(
      {"improve", "no gain", "goal past the default", 1,
       "working on from the default goals (" + parameter_text(first.goal_min_dihedral_deg) + "/" +
           parameter_text(first.goal_max_dihedral_deg) + " deg) towards " + parameter_text(params.goal_min_dihedral_deg) +
           "/" + parameter_text(params.goal_max_dihedral_deg) + " deg ended worse; the default goals' tets are kept",
       {{"min_dihedral_deg", high.min_dihedral_after_deg}, {"max_dihedral_deg", high.max_dihedral_after_deg}},
       {{"min_dihedral_deg", floor.min_dihedral_after_deg}, {"max_dihedral_deg", floor.max_dihedral_after_deg}}});
  result.min_dihedral_after_deg = floor.min_dihedral_after_deg;
  result.max_dihedral_after_deg = floor.max_dihedral_after_deg;
  result.boundary_max_displacement_relative = floor.boundary_max_displacement_relative;
  result.tets_after = floor.tets_after;
  result.below_goal_after = high.below_goal_before;  // the first stage's tets, below the goal asked
  return result;
}

}  // namespace meshprep
