#include "repair/remove_self_intersections.h"

#include "repair/same_place.h"

#include "repair/cut_face.h"
#include "repair/face_intersection.h"
#include "repair/separate_pinches.h"
#include "repair/split_nonmanifold.h"
#include "repair/weld_vertices.h"
#include "repair/winding_number.h"

#include "meshprep/core/union_find.h"
#include "meshprep/quality/face_edges.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/triangle_metrics.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace meshprep::detail {
namespace {

// A double holds a coordinate to 1.1e-16 of the largest one (the reach). Where a face passes
// within a rounding of another's edge or corner, the exact cut makes pieces thinner than that, and
// rounding their corners can fold them: after a pass that changed the surface, its points within
// 1e-10 of the reach of each other are welded (far below any feature a mesh for analysis holds,
// far above the rounding).
constexpr double kWeldReach = 1e-10;
// The poll (a stop, a budget) is called at each face the exact cut triangulates and at every this
// many crossing pairs it intersects: each a few microseconds of exact arithmetic.
constexpr std::size_t kPairsBetweenPolls = 64;

double reach(const TriangleSoup& soup) {
  double largest = 0;
  for (const Vec3& p : soup.points) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  return largest;
}

ExactTriangle exact_face(const TriangleSoup& soup, std::size_t f) {
  const Triangle& t = soup.triangles[f];
  return {exact_point(soup.points[t[0]]), exact_point(soup.points[t[1]]), exact_point(soup.points[t[2]])};
}

// Does p lie on the open segment (u, v)?
bool inside_edge(const ExactPoint& p, const ExactPoint& u, const ExactPoint& v) {
  const ExactPoint direction = minus(v, u), offset = minus(p, u);
  const ExactPoint c = cross(direction, offset);
  if (sgn(c[0]) != 0 || sgn(c[1]) != 0 || sgn(c[2]) != 0) return false;
  const Rational along = dot(offset, direction);
  return sgn(along) > 0 && along < dot(direction, direction);
}

// Does p lie in the closed triangle t, p in t's plane? (Projected along t's dominant axis.)
bool inside_coplanar_triangle(const ExactPoint& p, const ExactTriangle& t) {
  const int axis = dominant_axis(normal(t)), x = (axis + 1) % 3, y = (axis + 2) % 3;
  int signs[3];
  for (int i = 0; i < 3; ++i) {
    const ExactPoint &u = t[i], &v = t[(i + 1) % 3];
    signs[i] = sgn((v[x] - u[x]) * (p[y] - u[y]) - (v[y] - u[y]) * (p[x] - u[x]));
  }
  return (signs[0] >= 0 && signs[1] >= 0 && signs[2] >= 0) || (signs[0] <= 0 && signs[1] <= 0 && signs[2] <= 0);
}

// The surface with every face cut along where others meet it.
struct CutSurface {
  TriangleSoup soup;
  /// Per face of soup: a piece of a face lying on a coplanar face of lower index that faces the
  /// same way (the two are one piece of surface twice; the lower face's copy stays).
  std::vector<char> doubled;
  std::vector<std::size_t> source;  ///< per face of soup: the face of the input it is (a piece of)
  std::vector<char> was_cut;        ///< per face of the input
  std::size_t cut_faces = 0;
};

CutSurface cut_along_intersections(const TriangleSoup& surface,
                                   const std::vector<std::pair<std::size_t, std::size_t>>& pairs,
                                   const std::function<void()>& poll) {
  const std::size_t n = surface.triangles.size();
  std::map<std::size_t, ExactTriangle> exact;
  const auto exact_of = [&](std::size_t f) -> const ExactTriangle& {
    auto it = exact.find(f);
    if (it == exact.end()) it = exact.emplace(f, exact_face(surface, f)).first;
    return it->second;
  };
  std::map<std::size_t, std::vector<CutSegment>> cuts;
  std::map<std::size_t, std::vector<std::size_t>> same_facing_coplanar;
  std::size_t visited = 0;
  for (const auto& [f, g] : pairs) {
    if (++visited % kPairsBetweenPolls == 0) poll();
    const ExactTriangle &a = exact_of(f), &b = exact_of(g);
    FaceIntersection meet = intersect_faces(a, b);
    if (meet.in_a.empty() && meet.in_b.empty()) continue;
    auto& in_f = cuts[f];
    auto& in_g = cuts[g];
    in_f.insert(in_f.end(), meet.in_a.begin(), meet.in_a.end());
    in_g.insert(in_g.end(), meet.in_b.begin(), meet.in_b.end());
    if (meet.coplanar && sgn(dot(normal(a), normal(b))) > 0)
      same_facing_coplanar[std::max(f, g)].push_back(std::min(f, g));
  }
  // A cut ending inside an edge puts a point there, which the face on the other side of the edge
  // must have too, or the surface would crack there (a T-junction).
  std::map<std::uint64_t, std::vector<ExactPoint>> edge_points;
  for (const auto& [f, face_cuts] : cuts) {
    const Triangle& t = surface.triangles[f];
    const ExactTriangle& e = exact_of(f);
    for (const CutSegment& cut : face_cuts)
      for (const ExactPoint* p : {&cut.from, &cut.to})
        for (int i = 0; i < 3; ++i)
          if (inside_edge(*p, e[i], e[(i + 1) % 3])) edge_points[edge_key(t[i], t[(i + 1) % 3])].push_back(*p);
  }
  std::map<std::size_t, std::vector<ExactPoint>> boundary_points;
  for (std::size_t f = 0; f < n; ++f) {
    const Triangle& t = surface.triangles[f];
    for (int i = 0; i < 3; ++i) {
      const auto it = edge_points.find(edge_key(t[i], t[(i + 1) % 3]));
      if (it == edge_points.end()) continue;
      auto& points = boundary_points[f];
      points.insert(points.end(), it->second.begin(), it->second.end());
    }
  }

  CutSurface result;
  result.soup.points = surface.points;
  std::map<ExactPoint, std::uint32_t> point_ids;
  const auto id_of = [&](const ExactPoint& p) {
    const auto [it, added] = point_ids.emplace(p, static_cast<std::uint32_t>(result.soup.points.size()));
    if (added) result.soup.points.push_back(rounded(p));
    return it->second;
  };
  std::vector<char> to_cut(n, 0);
  for (const auto& entry : cuts) to_cut[entry.first] = 1;
  for (const auto& entry : boundary_points) to_cut[entry.first] = 1;
  for (std::size_t f = 0; f < n; ++f)
    if (to_cut[f])
      for (int i = 0; i < 3; ++i) point_ids.emplace(exact_of(f)[i], surface.triangles[f][i]);
  static const std::vector<CutSegment> kNoCuts;
  static const std::vector<ExactPoint> kNoPoints;
  for (std::size_t f = 0; f < n; ++f) {
    if (!to_cut[f]) {
      result.soup.triangles.push_back(surface.triangles[f]);
      result.doubled.push_back(0);
      result.source.push_back(f);
      continue;
    }
    ++result.cut_faces;
    poll();  // a face's exact triangulation: the costly unit
    const auto c = cuts.find(f);
    const auto b = boundary_points.find(f);
    const CutFace pieces =
        cut_face(exact_of(f), c == cuts.end() ? kNoCuts : c->second, b == boundary_points.end() ? kNoPoints : b->second);
    std::vector<std::uint32_t> ids(pieces.points.size());
    for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = i < 3 ? surface.triangles[f][i] : id_of(pieces.points[i]);
    const auto coplanar = same_facing_coplanar.find(f);
    for (const auto& piece : pieces.triangles) {
      result.soup.triangles.push_back({ids[piece[0]], ids[piece[1]], ids[piece[2]]});
      bool doubled = false;
      if (coplanar != same_facing_coplanar.end()) {
        ExactPoint centroid;
        for (int k = 0; k < 3; ++k)
          centroid[k] = (pieces.points[piece[0]][k] + pieces.points[piece[1]][k] + pieces.points[piece[2]][k]) / 3;
        for (const std::size_t g : coplanar->second) doubled = doubled || inside_coplanar_triangle(centroid, exact_of(g));
      }
      result.doubled.push_back(doubled);
      result.source.push_back(f);
    }
  }
  result.was_cut = std::move(to_cut);
  return result;
}

// Faces joined across edges that exactly two faces share: the pieces between the cut curves
// (where four or more meet), each wholly inside or outside the others. Copies of one point (where
// split_nonmanifold parted sheets) count as one, or a curve through them would not close.
// `uses`: sorted_face_edges(soup), or null; where no point has copies they are the merged
// surface's too.
std::vector<std::uint32_t> patches(const TriangleSoup& soup, const std::vector<FaceEdge>* uses) {
  const std::vector<std::uint32_t> canonical = first_at_same_place(soup.points);
  bool has_copies = false;
  for (std::uint32_t v = 0; v < canonical.size(); ++v) has_copies = has_copies || canonical[v] != v;
  std::vector<FaceEdge> merged_uses;
  if (has_copies || !uses) {
    TriangleSoup merged{{}, soup.triangles};
    merged.points.resize(soup.points.size());
    for (Triangle& t : merged.triangles)
      for (std::uint32_t& v : t) v = canonical[v];
    merged_uses = sorted_face_edges(merged);
    uses = &merged_uses;
  }
  const std::vector<FaceEdge>& edges = *uses;
  UnionFind sets(soup.triangles.size());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].key == edges[i].key) ++j;
    if (j - i == 2) sets.unite(edges[i].face, edges[i + 1].face);
    i = j;
  }
  std::vector<std::uint32_t> patch(soup.triangles.size());
  for (std::uint32_t f = 0; f < patch.size(); ++f) patch[f] = sets.find(f);
  return patch;
}

PointOffFace just_outside(const TriangleSoup& soup, std::size_t f) {
  const Triangle& t = soup.triangles[f];
  return point_off_face(soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]);
}

struct Pass {
  std::size_t pairs = 0, cut_faces = 0, removed_faces = 0, nested_components = 0, cavities = 0;
};

// `uses`: sorted_face_edges(surface), or null to sort them here, once past the return for a
// surface with nothing to judge.
Pass one_pass(TriangleSoup& surface, const std::vector<FaceEdge>* uses, bool keep_cavities,
              const std::function<void()>& poll) {
  Pass pass;
  const SelfIntersections found = find_self_intersections(surface);
  poll();
  pass.pairs = found.count;
  UnionFind parts(surface.points.size());
  for (const Triangle& t : surface.triangles) parts.unite(t[0], t[1]), parts.unite(t[0], t[2]);
  std::size_t part_count = 0;
  for (std::uint32_t v = 0; v < surface.points.size(); ++v) part_count += parts.find(v) == v;
  if (found.pairs.empty() && part_count <= 1) return pass;  // the clean surface: nothing to judge
  // Only closed parts have an inside: an open one (a sheet, a hole left open) has a fractional
  // winding number around it, so it is neither cut nor judged, and does not judge the others.
  std::vector<char> open(surface.points.size(), 0);
  const std::vector<FaceEdge> sorted_here = uses ? std::vector<FaceEdge>{} : sorted_face_edges(surface);
  const std::vector<FaceEdge>& edges = uses ? *uses : sorted_here;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].key == edges[i].key) ++j;
    if (j - i == 1) open[parts.find(edges[i].lo())] = 1;
    i = j;
  }
  const auto closed_face = [&](std::size_t f) { return !open[parts.find(surface.triangles[f][0])]; };
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (const auto& pair : found.pairs)
    if (closed_face(pair.first) && closed_face(pair.second)) pairs.push_back(pair);
  std::size_t closed_parts = 0;
  for (std::uint32_t v = 0; v < surface.points.size(); ++v) closed_parts += parts.find(v) == v && !open[v];
  if (pairs.empty() && closed_parts <= 1) return pass;
  std::vector<std::uint32_t> closed_faces;
  for (std::uint32_t f = 0; f < surface.triangles.size(); ++f)
    if (closed_face(f)) closed_faces.push_back(f);
  const WindingNumber winding_number(surface, std::move(closed_faces));

  CutSurface cut = cut_along_intersections(surface, pairs, poll);
  pass.cut_faces = cut.cut_faces;
  // Nothing cut (no pairs met: parts apart), the cut surface is the surface, its edges sorted.
  const std::vector<std::uint32_t> patch = patches(cut.soup, cut.cut_faces == 0 ? &edges : nullptr);
  // Each patch is judged at the point just outside its widest face that is not a doubled copy.
  std::map<std::uint32_t, std::pair<std::size_t, double>> widest;
  for (std::size_t f = 0; f < cut.soup.triangles.size(); ++f) {
    if (cut.doubled[f] || !closed_face(cut.source[f])) continue;
    const double inradius = just_outside(cut.soup, f).inradius;
    auto [it, added] = widest.emplace(patch[f], std::make_pair(f, inradius));
    if (!added && inradius > it->second.second) it->second = {f, inradius};
  }
  std::vector<std::pair<std::uint32_t, std::size_t>> judged(widest.size());
  std::size_t k = 0;
  for (const auto& [p, face] : widest) judged[k++] = {p, face.first};
  std::vector<long> winding(judged.size());
  tbb::parallel_for(std::size_t{0}, judged.size(), [&](std::size_t i) {
    winding[i] = std::lround(winding_number.at(just_outside(cut.soup, judged[i].second).point));
  });
  std::map<std::uint32_t, long> outside;
  for (std::size_t i = 0; i < judged.size(); ++i) outside[judged[i].first] = winding[i];

  // A part no cut touched is inside another if the winding just outside it is not 0: nested, it
  // is dropped, or kept as a cavity's wall (faced inwards) or, inside a cavity, as an island.
  std::map<std::uint32_t, char> part_was_cut;
  for (std::size_t f = 0; f < cut.soup.triangles.size(); ++f) {
    const std::uint32_t part = parts.find(surface.triangles[cut.source[f]][0]);
    part_was_cut[part] = part_was_cut[part] || cut.was_cut[cut.source[f]];
  }
  TriangleSoup kept;
  kept.points = std::move(cut.soup.points);
  kept.patch_names = surface.patch_names;
  // A kept piece stays in its face's patch.
  const auto keep = [&](const Triangle& t, std::size_t f) {
    kept.triangles.push_back(t);
    if (!surface.patches.empty()) kept.patches.push_back(surface.patches[cut.source[f]]);
  };
  std::map<std::uint32_t, char> nested_parts;
  for (std::size_t f = 0; f < cut.soup.triangles.size(); ++f) {
    const auto w = outside.find(patch[f]);
    const long winding_outside = w == outside.end() ? 1 : w->second;
    Triangle t = cut.soup.triangles[f];
    const std::uint32_t part = parts.find(surface.triangles[cut.source[f]][0]);
    if (open[part] || (!cut.doubled[f] && winding_outside == 0)) {
      keep(t, f);
      continue;
    }
    if (!part_was_cut[part] && winding_outside > 0) {
      nested_parts[part] = 1;
      if (keep_cavities) {
        if (winding_outside % 2 == 1) std::swap(t[1], t[2]);
        keep(t, f);
        continue;
      }
    }
    ++pass.removed_faces;
  }
  (keep_cavities ? pass.cavities : pass.nested_components) = nested_parts.size();
  surface = std::move(kept);
  return pass;
}

}  // namespace

SelfIntersectionCounts remove_self_intersections(TriangleSoup& surface, const std::vector<FaceEdge>& uses,
                                                 bool keep_cavities, const std::function<void()>& poll) {
  SelfIntersectionCounts counts;
  for (int round = 0; round < 3; ++round) {
    poll();
    // Every pass after the first looks at a surface the one before changed.
    const Pass pass = one_pass(surface, round == 0 ? &uses : nullptr, keep_cavities, poll);
    if (round == 0) counts.intersecting_pairs = pass.pairs;
    if (pass.cut_faces == 0 && pass.removed_faces == 0 && pass.cavities == 0) {
      counts.found_none = pass.pairs == 0;
      break;
    }
    counts.cut_faces += pass.cut_faces;
    counts.removed_faces += pass.removed_faces;
    counts.nested_components += pass.nested_components;
    counts.cavities += pass.cavities;
    weld_vertices(surface, kWeldReach * reach(surface));
    split_nonmanifold(surface, sorted_face_edges(surface));
    counts.separated_pinches += separate_pinches(surface);
  }
  return counts;
}

}  // namespace meshprep::detail
