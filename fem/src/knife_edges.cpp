#include "meshprep/fem/knife_edges.h"

#include "improve/surface_limits.h"
#include "meshprep/core/mesh_patches.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/triangle_bvh.h"
#include "meshprep/quality/triangle_intersection.h"
#include "meshprep/quality/triangle_metrics.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <tuple>
#include <unordered_map>

namespace meshprep {
namespace {

using VH = TriMesh::VertexHandle;
using FH = TriMesh::FaceHandle;
using EH = TriMesh::EdgeHandle;
using HH = TriMesh::HalfedgeHandle;
using Face = std::array<int, 3>;  // vertex indices, in the mesh's own orientation

// An edit changes the bounds of the edges around it, and may leave a neighbour a knife edge that
// another edit then opens: a few passes over the list settle it (each pass only keeps edits that
// raise the sorted list of bounds, so the passes cannot cycle).
constexpr int kMaxPasses = 4;
// Bounds closer than this count as equal: the two-tet term is a maximiser's figure, not exact.
constexpr double kLeastGainDeg = 1e-3;
// The barycentric lattice of this order samples a face for the displacement (15 points: the
// corners, three points on each edge, three inside).
constexpr int kSampleOrder = 4;

std::vector<Vec3> face_samples(const Vec3& a, const Vec3& b, const Vec3& c) {
  std::vector<Vec3> samples;
  for (int i = 0; i <= kSampleOrder; ++i)
    for (int j = 0; i + j <= kSampleOrder; ++j) {
      const int k = kSampleOrder - i - j;
      samples.push_back((i * a + j * b + k * c) / kSampleOrder);
    }
  return samples;
}

// A candidate edit: the faces it takes away and those it puts in their place, and the vertex it
// moves (a collapse's kept end, to its new position).
struct Edit {
  const char* name = "";
  std::vector<FH> old_faces;
  std::vector<Face> new_faces;
  int moved = -1;
  Vec3 moved_to = Vec3::Zero();
  HH collapse;  // invalid for a flip
  EH flip;
};

// An edge shorter than this share of max_deviation is a detail below the fidelity bound that the
// tets would still have to resolve (cow's cut curves meet within 4e-7 of the diagonal, and the
// tets crowding there stay under 7 degrees): it is collapsed if that costs no bound.
constexpr double kShortShareOfDeviation = 0.1;

// A knife edge, a cap face (face valid, edge the face's first) or a short edge, and its bound.
struct Knife {
  double bound = 0, angle = 0;
  EH edge;
  FH face;
  bool short_edge = false;
};

class KnifeEdgeOpener {
 public:
  KnifeEdgeOpener(TriMesh& mesh, const SoupView& reference, const KnifeEdgeParams& params)
      : mesh_(mesh),
        reference_(reference),
        params_(params),
        patches_(mesh),
        obtuse_weight_(std::sin(params.goal_min_dihedral_deg * M_PI / 180) /
                       std::sin((180 - params.goal_max_dihedral_deg) * M_PI / 180)) {
    double six_volume = 0;
    for (const FH f : mesh_.faces()) {
      auto v = mesh_.fv_iter(f);
      const Vec3 a = point(v->idx()), b = point((++v)->idx()), c = point((++v)->idx());
      six_volume += a.dot(b.cross(c));
    }
    outward_ = six_volume >= 0;
  }

  KnifeEdgeResult run() {
    KnifeEdgeResult result;
    std::vector<Knife> knives = knife_edges();
    result.knife_edges_before = knives.size();
    result.surface_bound_before_deg = lowest_bound(knives);
    for (int pass = 0; pass < kMaxPasses && !knives.empty(); ++pass) {
      index_faces();
      std::size_t made = 0;
      for (const Knife& knife : knives) {
        if (knife.face.is_valid() ? mesh_.status(knife.face).deleted() : mesh_.status(knife.edge).deleted()) continue;
        const double bound = knife.face.is_valid() ? face_bound(corners(knife.face)) : bound_and_angle(knife.edge).first;
        if (bound >= params_.goal_min_dihedral_deg && !(knife.short_edge && is_short(knife.edge)))
          continue;  // an earlier edit opened it
        if (open(knife, bound, result)) ++made;
      }
      knives = knife_edges();
      if (made == 0) break;
    }
    for (const Knife& knife : knives) {
      KnifeEdgePlace left;
      left.place = place_of(knife);
      left.kind = kind_of(knife);
      left.interior_angle_before_deg = left.interior_angle_after_deg = knife.angle;
      left.bound_before_deg = left.bound_after_deg = knife.bound;
      result.left.push_back(left);
    }
    result.knife_edges_after = knives.size();
    result.surface_bound_after_deg = lowest_bound(knives);
    if (!result.edits.empty()) mesh_.garbage_collection();
    return result;
  }

 private:
  Vec3 point(int v) const { return v == moved_ ? moved_to_ : to_eigen(mesh_.point(VH(v))); }

  Vec3 midpoint(EH e) const {
    const HH h = mesh_.halfedge_handle(e, 0);
    return 0.5 * (point(mesh_.from_vertex_handle(h).idx()) + point(mesh_.to_vertex_handle(h).idx()));
  }

  double lowest_bound(const std::vector<Knife>& knives) const {
    double lowest = params_.goal_min_dihedral_deg;
    for (const Knife& k : knives) lowest = std::min(lowest, k.bound);
    return lowest;
  }

  static const char* kind_of(const Knife& knife) { return knife.face.is_valid() ? "cap" : knife.short_edge ? "short" : "edge"; }

  bool is_short(EH e) const {
    const HH h = mesh_.halfedge_handle(e, 0);
    return (point(mesh_.to_vertex_handle(h).idx()) - point(mesh_.from_vertex_handle(h).idx())).norm() <
           kShortShareOfDeviation * params_.max_deviation;
  }

  Vec3 place_of(const Knife& knife) const {
    if (!knife.face.is_valid()) return midpoint(knife.edge);
    const Face c = corners(knife.face);
    return (point(c[0]) + point(c[1]) + point(c[2])) / 3.0;
  }

  // A face with no angle above this cannot cap the tets below the goal (the angles of a tet's
  // vertex figure on it are free enough); the others get face_bound_deg.
  double cap_angle() const { return 180 - 3 * params_.goal_min_dihedral_deg; }

  // The face's bound (surface_limits.h), capped at the goal; only worked out for a face with an
  // angle above cap_angle().
  double face_bound(const Face& f) const {
    const Vec3 a = point(f[0]), b = point(f[1]), c = point(f[2]);
    if (triangle_shape(a, b, c).max_angle_deg <= cap_angle()) return params_.goal_min_dihedral_deg;
    const std::array<Vec3, 3> outward = outward_ ? std::array<Vec3, 3>{a, b, c} : std::array<Vec3, 3>{a, c, b};
    return std::min(improve::face_bound_deg(outward, obtuse_weight_), params_.goal_min_dihedral_deg);
  }

  Face corners(FH f) const {
    Face c;
    int k = 0;
    for (const VH v : mesh_.fv_range(f)) c[k++] = v.idx();
    return c;
  }

  // The wedge at edge i -> j of a face (i, j, apex 0) whose neighbour across it is (j, i, apex 1),
  // oriented out of the solid (surface_limits.h).
  improve::BoundaryWedge wedge(int i, int j, int apex0, int apex1) const {
    if (outward_) return {point(i), point(j), {point(apex0), point(apex1)}};
    return {point(j), point(i), {point(apex0), point(apex1)}};
  }

  // The edge's bound (capped at the goal) and its interior angle.
  std::pair<double, double> bound_and_angle(int i, int j, int apex0, int apex1) const {
    const improve::BoundaryWedge w = wedge(i, j, apex0, apex1);
    const double angle = improve::interior_angle_deg(w);
    return {std::min(improve::wedge_bound_deg(w, angle, params_.goal_min_dihedral_deg), params_.goal_min_dihedral_deg),
            angle};
  }

  // The bound (capped at the goal) and interior angle of an edge of the mesh between two faces.
  std::pair<double, double> bound_and_angle(EH e) const {
    const HH h = mesh_.halfedge_handle(e, 0), o = mesh_.opposite_halfedge_handle(h);
    return bound_and_angle(mesh_.from_vertex_handle(h).idx(), mesh_.to_vertex_handle(h).idx(),
                           mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h)).idx(),
                           mesh_.to_vertex_handle(mesh_.next_halfedge_handle(o)).idx());
  }

  std::vector<Knife> knife_edges() const {
    std::vector<Knife> knives;
    for (const EH e : mesh_.edges()) {
      if (mesh_.status(e).deleted() || mesh_.is_boundary(e)) continue;
      const auto [bound, angle] = bound_and_angle(e);
      if (bound < params_.goal_min_dihedral_deg || is_short(e))
        knives.push_back({bound, angle, e, FH(), bound >= params_.goal_min_dihedral_deg});
    }
    for (const FH f : mesh_.faces()) {
      if (mesh_.status(f).deleted()) continue;
      const Face c = corners(f);
      const double bound = face_bound(c);
      if (bound < params_.goal_min_dihedral_deg)
        knives.push_back({bound, triangle_shape(point(c[0]), point(c[1]), point(c[2])).max_angle_deg,
                          mesh_.edge_handle(mesh_.halfedge_handle(f)), f, false});
    }
    std::sort(knives.begin(), knives.end(),
              [](const Knife& a, const Knife& b) {
      return a.bound != b.bound ? a.bound < b.bound : std::tie(a.edge, a.face) < std::tie(b.edge, b.face);
    });
    return knives;
  }

  // The bounds of every edge of `faces` (sorted, lowest first) and the smallest interior angle
  // among them, with the apex across an edge looked up first among `faces`, then in the mesh
  // (a neighbour the edit leaves as it is).
  std::pair<std::vector<double>, double> bounds_of(const std::vector<Face>& faces) const {
    std::map<std::pair<int, int>, int> apex;
    for (const Face& f : faces)
      for (int k = 0; k < 3; ++k) apex[{f[k], f[(k + 1) % 3]}] = f[(k + 2) % 3];
    std::vector<double> bounds;
    double smallest_angle = 360;
    for (const auto& [edge, apex0] : apex) {
      const auto [i, j] = edge;
      const auto across = apex.find({j, i});
      if (across != apex.end() && i > j) continue;  // counted from the other side
      int apex1 = -1;
      if (across != apex.end()) {
        apex1 = across->second;
      } else {
        const HH h = mesh_.find_halfedge(VH(j), VH(i));
        if (!h.is_valid() || mesh_.is_boundary(h)) continue;
        apex1 = mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h)).idx();
      }
      const auto [bound, angle] = bound_and_angle(i, j, apex0, apex1);
      bounds.push_back(bound);
      smallest_angle = std::min(smallest_angle, angle);
    }
    for (const Face& f : faces) bounds.push_back(face_bound(f));
    std::sort(bounds.begin(), bounds.end());
    return {bounds, smallest_angle};
  }

  // Whether the sorted bounds `after` beat `before`: the first that differs (a missing one counts
  // as the goal) is higher.
  bool better(const std::vector<double>& after, const std::vector<double>& before) const {
    const double goal = params_.goal_min_dihedral_deg;
    for (std::size_t k = 0; k < std::max(after.size(), before.size()); ++k) {
      const double a = k < after.size() ? after[k] : goal, b = k < before.size() ? before[k] : goal;
      if (a > b + kLeastGainDeg) return true;
      if (a < b - kLeastGainDeg) return false;
    }
    return false;
  }

  double smallest_face_angle(const std::vector<Face>& faces) const {
    double smallest = 180;
    for (const Face& f : faces) smallest = std::min(smallest, triangle_shape(point(f[0]), point(f[1]), point(f[2])).min_angle_deg);
    return smallest;
  }

  // The edit's displacement: the new faces' samples from the reference, the old faces' from the
  // new ones (points at the positions before the edit, then after). Infinity if a new face has no area.
  double displacement(const Edit& edit, const std::vector<Face>& old_faces) {
    double worst = 0;
    std::vector<std::array<Vec3, 3>> old_triangles;
    for (const Face& f : old_faces) old_triangles.push_back({point(f[0]), point(f[1]), point(f[2])});
    begin(edit);
    std::vector<std::array<Vec3, 3>> new_triangles;
    for (const Face& f : edit.new_faces) new_triangles.push_back({point(f[0]), point(f[1]), point(f[2])});
    end();
    for (const auto& t : new_triangles) {
      if (!triangle_has_area(t[0], t[1], t[2])) return std::numeric_limits<double>::infinity();
      for (const Vec3& s : face_samples(t[0], t[1], t[2]))
        worst = std::max(worst, std::sqrt(reference_bvh_.closest_point(s).squared_distance));
    }
    for (const auto& t : old_triangles)
      for (const Vec3& s : face_samples(t[0], t[1], t[2])) {
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto& n : new_triangles) nearest = std::min(nearest, (closest_point_on_triangle(s, n[0], n[1], n[2]) - s).norm());
        worst = std::max(worst, nearest);
      }
    return worst;
  }

  void begin(const Edit& edit) { moved_ = edit.moved, moved_to_ = edit.moved_to; }
  void end() { moved_ = -1; }

  // The faces as they are at the start of a pass, in a hierarchy for the crossing checks; the
  // faces an edit has changed since (`touched_`) are looked at on top of it.
  void index_faces() {
    snapshot_.points.clear();
    snapshot_.triangles.clear();
    for (const VH v : mesh_.all_vertices()) snapshot_.points.push_back(to_eigen(mesh_.point(v)));
    for (const FH f : mesh_.all_faces()) {
      if (mesh_.status(f).deleted()) {
        snapshot_.triangles.push_back({0, 0, 0});  // never visited: deleted faces are passed over
        continue;
      }
      const Face c = corners(f);
      snapshot_.triangles.push_back({static_cast<std::uint32_t>(c[0]), static_cast<std::uint32_t>(c[1]),
                                     static_cast<std::uint32_t>(c[2])});
    }
    faces_ = std::make_unique<TriangleBvh>(snapshot_);
    touched_.clear();
  }

  // Crossing face pairs among `faces` and the mesh's faces near them (other than `left_out`).
  std::size_t crossings(const std::vector<Face>& faces, const std::vector<FH>& left_out, const Box3& near) const {
    TriangleSoup soup;
    std::unordered_map<int, std::uint32_t> index;
    const auto add = [&](const Face& f) {
      Triangle t;
      for (int k = 0; k < 3; ++k) {
        const auto [at, added] = index.emplace(f[k], static_cast<std::uint32_t>(soup.points.size()));
        if (added) soup.points.push_back(point(f[k]));
        t[k] = at->second;
      }
      soup.triangles.push_back(t);
    };
    for (const Face& f : faces) add(f);
    const auto consider = [&](FH f) {
      if (mesh_.status(f).deleted() || std::find(left_out.begin(), left_out.end(), f) != left_out.end()) return;
      Box3 box;
      for (const VH v : mesh_.fv_range(f)) box.extend(point(v.idx()));
      if (box.intersects(near)) add(corners(f));
    };
    faces_->for_each_overlapping(near, [&](std::size_t f) {
      if (std::find(touched_.begin(), touched_.end(), FH(static_cast<int>(f))) == touched_.end())
        consider(FH(static_cast<int>(f)));
    });
    for (const FH f : touched_) consider(f);
    return find_self_intersections(soup).count;
  }

  // The flip of e and the collapses of the edges of its two faces; only e's collapses for a short edge.
  std::vector<Edit> candidates(EH e, bool only_collapses_of_e = false) const {
    std::vector<Edit> edits;
    const HH h = mesh_.halfedge_handle(e, 0), o = mesh_.opposite_halfedge_handle(h);
    const int u = mesh_.from_vertex_handle(h).idx(), v = mesh_.to_vertex_handle(h).idx();
    const int a0 = mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h)).idx();
    const int a1 = mesh_.to_vertex_handle(mesh_.next_halfedge_handle(o)).idx();
    const FH f0 = mesh_.face_handle(h), f1 = mesh_.face_handle(o);
    if (!only_collapses_of_e && mesh_.is_flip_ok(e) && patches_.of(f0) == patches_.of(f1)) {
      Edit flip;
      flip.name = "flip";
      flip.flip = e;
      flip.old_faces = {f0, f1};
      flip.new_faces = {{u, a1, a0}, {a1, v, a0}};  // the quad u, a1, v, a0 cut along a1-a0
      edits.push_back(flip);
    }
    const std::pair<int, int> sides[] = {{u, v}, {u, a0}, {v, a0}, {u, a1}, {v, a1}};
    for (const auto& [p, q] : only_collapses_of_e ? std::vector<std::pair<int, int>>{{u, v}}
                                                   : std::vector<std::pair<int, int>>(std::begin(sides), std::end(sides)))
      for (int way = 0; way < 3; ++way) {  // p into q, q into p, p into q at the middle
        const int from = way == 1 ? q : p, to = way == 1 ? p : q;
        const HH c = mesh_.find_halfedge(VH(from), VH(to));
        if (!c.is_valid() || !mesh_.is_collapse_ok(c)) continue;
        Edit collapse;
        collapse.name = "collapse";
        collapse.collapse = c;
        collapse.moved = to;
        collapse.moved_to = way == 2 ? Vec3(0.5 * (point(from) + point(to))) : point(to);
        std::vector<FH> ring;
        for (const int end : {from, to})
          for (const FH f : mesh_.vf_range(VH(end)))
            if (std::find(ring.begin(), ring.end(), f) == ring.end()) ring.push_back(f);
        collapse.old_faces = ring;
        for (const FH f : ring) {
          Face c2 = corners(f);
          const bool has_from = std::count(c2.begin(), c2.end(), from) > 0, has_to = std::count(c2.begin(), c2.end(), to) > 0;
          if (has_from && has_to) continue;  // the collapse removes it
          for (int& k : c2)
            if (k == from) k = to;
          collapse.new_faces.push_back(c2);
        }
        edits.push_back(collapse);
      }
    return edits;
  }

  struct Scored {
    std::size_t edit = 0;
    std::vector<Face> old_faces;  // the corners of the faces it takes away
    std::vector<double> bounds;
    double smallest_angle = 0;
  };

  // Tries the candidates on one knife edge, best first; makes the first that passes every check.
  bool open(const Knife& knife, double bound_before, KnifeEdgeResult& result) {
    std::vector<Edit> edits;
    if (knife.face.is_valid()) {
      for (const HH h : mesh_.fh_range(knife.face)) {
        std::vector<Edit> more = candidates(mesh_.edge_handle(h));
        edits.insert(edits.end(), more.begin(), more.end());
      }
    } else {
      edits = candidates(knife.edge, knife.short_edge);
    }
    std::vector<Scored> scored;
    for (std::size_t k = 0; k < edits.size(); ++k) {
      const Edit& edit = edits[k];
      std::vector<Face> old_faces;
      for (const FH f : edit.old_faces) old_faces.push_back(corners(f));
      const auto [old_bounds, old_angle] = bounds_of(old_faces);
      const double old_shape = smallest_face_angle(old_faces);
      begin(edit);
      auto [new_bounds, new_angle] = bounds_of(edit.new_faces);
      const double new_shape = smallest_face_angle(edit.new_faces);
      end();
      // A short edge's collapse need only cost no bound; the other edits must raise them.
      if (knife.short_edge ? better(old_bounds, new_bounds) : !better(new_bounds, old_bounds)) continue;
      if (new_shape < std::min(old_shape, params_.goal_min_dihedral_deg)) continue;
      scored.push_back({k, std::move(old_faces), std::move(new_bounds), new_angle});
    }
    std::stable_sort(scored.begin(), scored.end(), [&](const Scored& a, const Scored& b) { return better(a.bounds, b.bounds); });
    for (const Scored& s : scored) {
      const Edit& edit = edits[s.edit];
      const std::vector<Face>& old_faces = s.old_faces;
      const double moved = displacement(edit, old_faces);
      if (!(moved <= params_.max_deviation)) continue;
      Box3 near;
      for (const Face& f : old_faces)
        for (const int v : f) near.extend(point(v));
      begin(edit);
      for (const Face& f : edit.new_faces)
        for (const int v : f) near.extend(point(v));
      const std::size_t after = crossings(edit.new_faces, edit.old_faces, near);
      end();
      if (after > crossings(old_faces, edit.old_faces, near)) continue;
      KnifeEdgePlace place;
      place.place = place_of(knife);
      place.kind = kind_of(knife);
      place.bound_before_deg = bound_before;
      place.interior_angle_before_deg = knife.angle;
      place.bound_after_deg = s.bounds.empty() ? params_.goal_min_dihedral_deg : s.bounds.front();
      place.interior_angle_after_deg = s.smallest_angle;
      place.displacement = moved;
      place.edit = edit.name;
      make(edit);
      result.edits.push_back(place);
      result.max_displacement = std::max(result.max_displacement, moved);
      return true;
    }
    return false;
  }

  void make(const Edit& edit) {
    if (edit.flip.is_valid()) {
      mesh_.flip(edit.flip);
      touched_.insert(touched_.end(), edit.old_faces.begin(), edit.old_faces.end());  // a flip keeps its two faces
      return;
    }
    mesh_.set_point(VH(edit.moved), to_openmesh(edit.moved_to));
    mesh_.collapse(edit.collapse);
    for (const FH f : mesh_.vf_range(VH(edit.moved))) touched_.push_back(f);
  }

  TriMesh& mesh_;
  const SoupView& reference_;
  TriangleBvh reference_bvh_{reference_};
  const KnifeEdgeParams& params_;
  FacePatches patches_;
  TriangleSoup snapshot_;  // index_faces()
  std::unique_ptr<TriangleBvh> faces_;
  std::vector<FH> touched_;
  double obtuse_weight_;  // tet_objective.h: a goal_max angle scores like a goal_min one
  bool outward_ = true;
  int moved_ = -1;  // while an edit is weighed: the vertex it moves, and where
  Vec3 moved_to_ = Vec3::Zero();
};

}  // namespace

KnifeEdgeResult open_knife_edges(TriMesh& mesh, const SoupView& reference, const KnifeEdgeParams& params) {
  const auto start = std::chrono::steady_clock::now();
  KnifeEdgeResult result = KnifeEdgeOpener(mesh, reference, params).run();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

nlohmann::ordered_json to_json(const KnifeEdgeResult& result) {
  const auto places = [](const std::vector<KnifeEdgePlace>& list, bool edits) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const KnifeEdgePlace& p : list) {
      nlohmann::ordered_json j = {{"kind", p.kind},
                                  {"place", {p.place.x(), p.place.y(), p.place.z()}},
                                  {"angle_before_deg", p.interior_angle_before_deg},
                                  {"bound_before_deg", p.bound_before_deg}};
      if (edits) {
        j["smallest_interior_angle_after_deg"] = p.interior_angle_after_deg;
        j["bound_after_deg"] = p.bound_after_deg;
        j["displacement"] = p.displacement;
        j["edit"] = p.edit;
      }
      out.push_back(j);
    }
    return out;
  };
  return {{"knife_edges_before", result.knife_edges_before},
          {"knife_edges_after", result.knife_edges_after},
          {"surface_bound_before_deg", result.surface_bound_before_deg},
          {"surface_bound_after_deg", result.surface_bound_after_deg},
          {"max_displacement", result.max_displacement},
          {"edits", places(result.edits, true)},
          {"left", places(result.left, false)},
          {"seconds", result.seconds}};
}

}  // namespace meshprep
