#include "meshprep/quality/report.h"

#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/surface_distance.h"
#include "meshprep/quality/topology.h"
#include "meshprep/quality/triangle_bvh.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <chrono>
#include <numeric>

namespace meshprep {
namespace {

constexpr std::size_t kListedPairs = 100;

void fill_topology(const SoupView& soup, QualityReport& r) {
  const Topology topo = analyze_topology(soup);
  r.vertices = topo.referenced_vertices;
  r.isolated_vertices = topo.isolated_vertices;
  r.faces = soup.triangles.size();
  r.edges = topo.edges;
  r.components = topo.components;
  r.border_edges = topo.border_edges;
  r.boundary_loops = topo.boundary_loops;
  r.non_manifold_edges = topo.non_manifold_edges;
  r.non_manifold_vertices = topo.non_manifold_vertices;
  r.closed = topo.closed;
  r.manifold = topo.manifold;
  r.oriented = topo.oriented;
  r.euler_characteristic = topo.euler_characteristic;
  r.genus = topo.genus;
  r.duplicate_faces = topo.duplicate_faces;
  // The divergence theorem gives the enclosed volume when every edge has exactly two faces
  // traversing it in opposite directions (non-manifold vertices do not matter for it).
  const bool volume_defined = topo.closed && topo.non_manifold_edges == 0 && topo.inconsistent_edges == 0 &&
                              topo.repeated_index_faces == 0 && !soup.triangles.empty();
  if (volume_defined) r.volume = signed_volume(soup);
}

void fill_shape(const SoupView& soup, std::size_t n_worst, QualityReport& r) {
  r.face_shapes = triangle_shapes(soup);
  const std::size_t n = r.face_shapes.size();
  std::vector<double> rr, ar, amin, amax, area;
  for (auto* v : {&rr, &ar, &amin, &amax, &area}) v->reserve(n);
  std::size_t below20 = 0, below10 = 0, rr_above2 = 0;
  for (const TriangleShape& s : r.face_shapes) {
    r.area += s.area;
    if (s.degenerate) {
      ++r.degenerate_faces;
      continue;
    }
    rr.push_back(s.radius_ratio);
    ar.push_back(s.aspect_ratio);
    amin.push_back(s.min_angle_deg);
    amax.push_back(s.max_angle_deg);
    area.push_back(s.area);
    below20 += s.min_angle_deg < 20.0;
    below10 += s.min_angle_deg < 10.0;
    rr_above2 += s.radius_ratio > 2.0;
  }
  const double counted = static_cast<double>(rr.size());
  if (!rr.empty()) {
    r.faces_min_angle_below_20 = static_cast<double>(below20) / counted;
    r.faces_min_angle_below_10 = static_cast<double>(below10) / counted;
    r.faces_radius_ratio_above_2 = static_cast<double>(rr_above2) / counted;
  }
  r.radius_ratio = summarize(std::move(rr));
  r.aspect_ratio = summarize(std::move(ar));
  r.min_angle_deg = summarize(std::move(amin));
  r.max_angle_deg = summarize(std::move(amax));
  r.area_distribution = summarize(std::move(area));

  // Worst first by radius ratio (degenerate faces have +inf); ties by index for determinism.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  const std::size_t k = std::min(n_worst, n);
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k), order.end(),
                    [&](std::size_t a, std::size_t b) {
                      const double ra = r.face_shapes[a].radius_ratio, rb = r.face_shapes[b].radius_ratio;
                      return ra > rb || (ra == rb && a < b);
                    });
  for (std::size_t i = 0; i < k; ++i) r.worst_faces.push_back({order[i], r.face_shapes[order[i]]});
}

void fill_bbox(const SoupView& soup, QualityReport& r) {
  const Box3 box = bounding_box(soup);
  if (box.isEmpty()) return;
  r.bbox_min = box.min();
  r.bbox_max = box.max();
  r.bbox_diagonal = box.diagonal().norm();
}

ReferenceComparison compare_with(const SoupView& soup, const QualityReport& r, const TriangleSoup& reference,
                                 const QualityParams& params) {
  DistanceParams dp;
  dp.samples = params.distance_samples;
  dp.seed = params.seed;
  SurfaceDistance d;
  QualityReport ref;  // the reference's topology, for its volume
  tbb::parallel_invoke([&] { d = surface_distance(soup, reference, dp); },
                       [&] {
                         if (r.volume) fill_topology(reference, ref);
                       });
  ReferenceComparison c;
  c.reference_bbox_diagonal = bbox_diagonal(reference);
  const double diag = c.reference_bbox_diagonal > 0 ? c.reference_bbox_diagonal : 1.0;
  c.hausdorff = d.hausdorff();
  c.hausdorff_relative = c.hausdorff / diag;
  c.rms_relative = d.rms() / diag;
  c.mean_relative = d.mean() / diag;
  c.samples = d.a_to_b.points;
  if (r.volume && ref.volume && *ref.volume != 0) c.volume_change_percent = (*r.volume - *ref.volume) / *ref.volume * 100.0;
  return c;
}

}  // namespace

QualityReport analyze_quality(const SoupView& soup, const QualityParams& params, const TriangleSoup* reference) {
  const auto start = std::chrono::steady_clock::now();
  QualityReport r;
  // Three independent parts, each filling its own fields of r: the topology (serial: union-finds
  // over the sorted edges) runs beside the other two, so that a second core has work throughout.
  tbb::parallel_invoke([&] { fill_topology(soup, r); },
                       [&] {
                         fill_shape(soup, params.worst_faces, r);
                         fill_bbox(soup, r);
                       },
                       [&] {
                         if (params.self_intersection_cap == 0) return;
                         SelfIntersections si = find_self_intersections(soup, params.self_intersection_cap);
                         r.self_intersections = si.count;
                         r.self_intersections_capped = si.capped;
                         si.pairs.resize(std::min(si.pairs.size(), kListedPairs));
                         r.self_intersecting_pairs = std::move(si.pairs);
                       });
  if (reference) r.reference = compare_with(soup, r, *reference, params);
  r.time_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

std::size_t new_self_intersections(const QualityReport& output, std::size_t input_pairs) {
  return output.self_intersections > input_pairs ? output.self_intersections - input_pairs : 0;
}

}  // namespace meshprep
