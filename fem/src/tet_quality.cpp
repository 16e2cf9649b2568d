// Tet quality: dihedral angles, radius-edge ratio, and the Verdict library's scaled Jacobian and
// aspect ratio (C. J. Stimpson, C. D. Ernst, P. Knupp, P. P. Pebay, D. Thompson, "The Verdict
// Geometric Quality Library", SAND2007-1751, 2007; sandialabs/verdict V_TetMetric.cpp).
#include "meshprep/fem/tet_quality.h"

#include "quadratic_jacobian.h"

#include "meshprep/core/errors.h"
#include "meshprep/quality/json_values.h"
#include "meshprep/report/number_format.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <tuple>
#include <utility>

namespace meshprep {
namespace {

using Json = nlohmann::ordered_json;

constexpr double kDegreesPerRadian = 180.0 / M_PI;

// Outward normals (unnormalised) of the faces opposite p0..p3 of a positively oriented tet. For an
// inverted tet all four point inward, which leaves the angles between them unchanged. Each has
// twice its face's area as its length.
std::array<Vec3, 4> face_normals(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  return {(p2 - p1).cross(p3 - p1), (p3 - p0).cross(p2 - p0), (p1 - p0).cross(p3 - p0),
          (p2 - p0).cross(p1 - p0)};
}

// Every pair of faces meets at one edge (the edge opposite the two other vertices); the interior
// dihedral angle there is pi minus the angle between the outward normals. atan2(|n1 x n2|, n1.n2)
// stays accurate near 0 and pi, where acos of a normalised dot product does not; but it is the
// dearest part of a tet's shape, so the six cosines pick the pairs that can hold the extremes and
// only those get it. A cosine is off by a few ulps, so every pair within kCosineMargin of the
// extreme cosine is a candidate: the result is the six atan2's minimum and maximum exactly.
std::pair<double, double> dihedral_range_deg(const std::array<Vec3, 4>& normals) {
  constexpr double kCosineMargin = 1e-12;
  std::array<double, 4> lengths;
  for (int k = 0; k < 4; ++k) lengths[k] = normals[k].norm();
  std::array<double, 6> cosines;
  std::array<std::pair<int, int>, 6> pairs;
  int n = 0;
  for (int k = 0; k < 4; ++k)
    for (int l = k + 1; l < 4; ++l, ++n) {
      pairs[n] = {k, l};
      cosines[n] = normals[k].dot(normals[l]) / (lengths[k] * lengths[l]);
    }
  // A zero normal (a face of zero area, or one whose length underflows) gives a cosine that is not
  // finite: then every pair is a candidate.
  const auto [lowest, highest] = std::minmax_element(cosines.begin(), cosines.end());
  const bool all = std::any_of(cosines.begin(), cosines.end(), [](double c) { return !std::isfinite(c); });
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (int i = 0; i < 6; ++i) {
    // The largest angle between normals (smallest dihedral) has the lowest cosine, and the reverse.
    const bool min_candidate = all || cosines[i] <= *lowest + kCosineMargin;
    const bool max_candidate = all || cosines[i] >= *highest - kCosineMargin;
    if (!min_candidate && !max_candidate) continue;
    const auto [k, l] = pairs[i];
    const double between_normals = std::atan2(normals[k].cross(normals[l]).norm(), normals[k].dot(normals[l]));
    const double dihedral = (M_PI - between_normals) * kDegreesPerRadian;
    lo = std::min(lo, dihedral);
    hi = std::max(hi, dihedral);
  }
  return {lo, hi};
}

// The six edge lengths, in the order 01 02 03 12 13 23.
std::array<double, 6> edge_lengths(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  return {(p1 - p0).norm(), (p2 - p0).norm(), (p3 - p0).norm(), (p2 - p1).norm(), (p3 - p1).norm(), (p3 - p2).norm()};
}

// Circumradius R = |a^2 (b x c) + b^2 (c x a) + c^2 (a x b)| / (12 V), a, b, c the edges from p0
// (the circumcentre relative to p0 is that vector over 2 a.(b x c) = 12 V).
double circumradius(const Vec3& a, const Vec3& b, const Vec3& c, double volume) {
  if (volume == 0) return std::numeric_limits<double>::infinity();
  const Vec3 centre = a.squaredNorm() * b.cross(c) + b.squaredNorm() * c.cross(a) + c.squaredNorm() * a.cross(b);
  return centre.norm() / (12.0 * std::abs(volume));
}

// Verdict's tet_scaled_jacobian: J is the same at every corner, so the smallest corner value of a
// positive tet is J over the largest product of a corner's three edge lengths. |J| never exceeds a
// corner's product (Hadamard's inequality); Verdict still takes |J| into the maximum, which keeps
// the result in [-1, 1] under round-off. Lengths, not squared lengths, keep the products (of
// degree 3) within the double range for any coordinates the readers accept.
double scaled_jacobian(const std::array<double, 6>& l, double jacobian) {
  const double largest = std::max({l[0] * l[1] * l[2], l[0] * l[3] * l[4], l[1] * l[3] * l[5], l[2] * l[4] * l[5],
                                   std::abs(jacobian)});
  if (largest == 0) return 0;  // every corner at one point
  return std::sqrt(2.0) * jacobian / largest;
}

// Verdict's tet_aspect_ratio: h_max / (2 sqrt(6) r) with the inradius r = 3 |V| / A, A the faces'
// area, so h_max A / (6 sqrt(6) |V|); 2 sqrt(6) r is the edge of the regular tet of inradius r,
// hence 1 for it.
double aspect_ratio(const std::array<double, 6>& l, const std::array<Vec3, 4>& normals, double volume) {
  if (volume == 0) return std::numeric_limits<double>::infinity();
  double area = 0;
  for (const Vec3& n : normals) area += 0.5 * n.norm();
  return *std::max_element(l.begin(), l.end()) * area / (6.0 * std::sqrt(6.0) * std::abs(volume));
}

void check_point_indices(const TetMesh& mesh) {
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (const auto v : mesh.tets[t])
      if (v >= mesh.points.size())
        throw InvalidInput("tet mesh: tet " + std::to_string(t) + " references point " + std::to_string(v) +
                           " of " + std::to_string(mesh.points.size()));
  if (!mesh.quadratic()) return;
  if (mesh.tet_edge_nodes.size() != mesh.tets.size())
    throw InvalidInput("tet mesh: " + std::to_string(mesh.tet_edge_nodes.size()) + " rows of mid-edge nodes for " +
                       std::to_string(mesh.tets.size()) + " tets");
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (const auto v : mesh.tet_edge_nodes[t])
      if (v >= mesh.points.size())
        throw InvalidInput("tet mesh: tet " + std::to_string(t) + " has mid-edge node " + std::to_string(v) + " of " +
                           std::to_string(mesh.points.size()) + " points");
}

// Whether a mid-edge node of tet t is off its edge's midpoint by more than 1e-9 of the edge's length
// (a straight node written and read back, or computed another way, is within round-off of it).
bool curved(const std::array<Vec3, 10>& x) {
  for (int e = 0; e < 6; ++e) {
    const Vec3 &a = x[kTetEdges[e][0]], &b = x[kTetEdges[e][1]];
    if ((x[4 + e] - 0.5 * (a + b)).norm() > 1e-9 * (b - a).norm()) return true;
  }
  return false;
}

QuadraticTetQuality quadratic_quality(const TetMesh& mesh, const std::vector<TetShape>& shapes) {
  QuadraticTetQuality q;
  std::vector<double>& per_tet = q.min_scaled_jacobian_per_tet;
  per_tet.resize(mesh.tets.size());
  std::vector<std::uint8_t> nonpositive(mesh.tets.size()), is_curved(mesh.tets.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.tets.size(), 4096), [&](const auto& range) {
    for (std::size_t t = range.begin(); t != range.end(); ++t) {
      const std::array<Vec3, 10> x = detail::tet_nodes(mesh, t);
      const detail::NodalJacobian jacobian = detail::nodal_jacobian(x);
      per_tet[t] = jacobian.min_scaled;
      nonpositive[t] = shapes[t].volume <= 0 || !(jacobian.min > 0);
      is_curved[t] = curved(x);
    }
  });
  q.nonpositive_jacobian_tets = static_cast<std::size_t>(std::count(nonpositive.begin(), nonpositive.end(), 1));
  q.curved_tets = static_cast<std::size_t>(std::count(is_curved.begin(), is_curved.end(), 1));
  q.min_scaled_jacobian = summarize(per_tet);
  return q;
}

// The `count` tets of smallest dihedral angle, smallest first; ties by index, so that the list
// does not depend on the sort's implementation.
std::vector<WorstTet> worst_tets(const TetMesh& mesh, const std::vector<TetShape>& shapes, std::size_t count) {
  std::vector<std::size_t> order(shapes.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  count = std::min(count, order.size());
  const auto by_angle = [&shapes](std::size_t a, std::size_t b) {
    return std::make_pair(shapes[a].min_dihedral_deg, a) < std::make_pair(shapes[b].min_dihedral_deg, b);
  };
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(count), order.end(), by_angle);
  std::vector<WorstTet> worst(count);
  for (std::size_t i = 0; i < count; ++i) {
    WorstTet& w = worst[i];
    w.index = order[i];
    w.region = mesh.tet_regions[w.index];
    for (const auto v : mesh.tets[w.index]) w.centre += mesh.points[v] / 4.0;
    w.shape = shapes[w.index];
  }
  return worst;
}

Json worst_tet_json(const WorstTet& w) {
  return {{"index", w.index},
          {"region", w.region},
          {"centre", {w.centre.x(), w.centre.y(), w.centre.z()}},
          {"min_dihedral_deg", w.shape.min_dihedral_deg},
          {"max_dihedral_deg", w.shape.max_dihedral_deg},
          {"radius_edge_ratio", json_number(w.shape.radius_edge_ratio)},
          {"scaled_jacobian", w.shape.scaled_jacobian},
          {"aspect_ratio", json_number(w.shape.aspect_ratio)}};
}

}  // namespace

TetShape tet_shape(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  const Vec3 a = p1 - p0, b = p2 - p0, c = p3 - p0;
  const double jacobian = a.dot(b.cross(c));
  const std::array<Vec3, 4> normals = face_normals(p0, p1, p2, p3);
  const std::array<double, 6> lengths = edge_lengths(p0, p1, p2, p3);
  TetShape s;
  s.volume = jacobian / 6.0;
  std::tie(s.min_dihedral_deg, s.max_dihedral_deg) = dihedral_range_deg(normals);
  s.radius_edge_ratio = circumradius(a, b, c, s.volume) / *std::min_element(lengths.begin(), lengths.end());
  s.scaled_jacobian = scaled_jacobian(lengths, jacobian);
  s.aspect_ratio = aspect_ratio(lengths, normals, s.volume);
  return s;
}

bool certainly_positive(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  constexpr double eps = std::numeric_limits<double>::epsilon() / 2;  // 2^-53, Shewchuk's epsilon
  constexpr double bound_a = (7.0 + 56.0 * eps) * eps;
  const Vec3 u = b - a, v = c - a, w = d - a;
  const double vy_wz = v.y() * w.z(), vz_wy = v.z() * w.y();
  const double vz_wx = v.z() * w.x(), vx_wz = v.x() * w.z();
  const double vx_wy = v.x() * w.y(), vy_wx = v.y() * w.x();
  const double det = u.x() * (vy_wz - vz_wy) + u.y() * (vz_wx - vx_wz) + u.z() * (vx_wy - vy_wx);
  const double permanent = std::abs(u.x()) * (std::abs(vy_wz) + std::abs(vz_wy)) +
                           std::abs(u.y()) * (std::abs(vz_wx) + std::abs(vx_wz)) +
                           std::abs(u.z()) * (std::abs(vx_wy) + std::abs(vy_wx));
  return det > bound_a * permanent;
}

std::vector<std::size_t> flat_tets(const TetMesh& mesh) {
  std::vector<std::size_t> flat;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& v = mesh.tets[t];
    if (!certainly_positive(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.points[v[3]]))
      flat.push_back(t);
  }
  return flat;
}

std::string describe_flat_tets(const TetMesh& mesh) {
  const std::vector<std::size_t> flat = flat_tets(mesh);
  if (flat.empty()) return {};
  Vec3 centre = Vec3::Zero();
  for (const std::uint32_t v : mesh.tets[flat.front()]) centre += mesh.points[v] / 4;
  const auto number = [](double x) { return format_number(x, 6); };
  return std::to_string(flat.size()) + (flat.size() == 1 ? " tet is" : " tets are") +
         " flat or inverted (the volume is not positive beyond rounding); the first, tet " + std::to_string(flat.front()) +
         ", at (" + number(centre.x()) + ", " + number(centre.y()) + ", " + number(centre.z()) + ")";
}

std::vector<TetShape> tet_shapes(const TetMesh& mesh, const std::function<bool()>& cancelled) {
  check_point_indices(mesh);
  std::vector<TetShape> shapes(mesh.tets.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, shapes.size(), 4096), [&](const auto& range) {
    if (cancelled && cancelled()) throw Cancelled("tet quality stopped");
    for (std::size_t t = range.begin(); t != range.end(); ++t) {
      const auto& v = mesh.tets[t];
      shapes[t] = tet_shape(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.points[v[3]]);
    }
  });
  return shapes;
}

void check_tet_mesh_structure(const TetMesh& mesh) {
  if (mesh.tet_regions.size() != mesh.tets.size())
    throw InvalidInput("tet mesh: " + std::to_string(mesh.tet_regions.size()) + " region tags for " +
                       std::to_string(mesh.tets.size()) + " tets");
  check_point_indices(mesh);
}

TetQualityReport analyze_tet_quality(const TetMesh& mesh, std::size_t worst_tet_count,
                                     const std::function<bool()>& cancelled) {
  check_tet_mesh_structure(mesh);
  const std::vector<TetShape> shapes = tet_shapes(mesh, cancelled);
  TetQualityReport r;
  r.points = mesh.points.size();
  r.tetrahedra = mesh.tets.size();
  std::vector<double> max_dihedral;
  max_dihedral.reserve(shapes.size());
  r.min_dihedral_per_tet.reserve(shapes.size());
  r.radius_edge_per_tet.reserve(shapes.size());
  r.scaled_jacobian_per_tet.reserve(shapes.size());
  r.aspect_ratio_per_tet.reserve(shapes.size());
  std::size_t below_10 = 0;
  for (std::size_t t = 0; t < shapes.size(); ++t) {
    const TetShape& s = shapes[t];
    r.volume += s.volume;
    if (s.volume <= 0) ++r.inverted_tets;
    if (s.min_dihedral_deg < 10.0) ++below_10;
    ++r.tets_per_region[mesh.tet_regions[t]];
    r.min_dihedral_per_tet.push_back(s.min_dihedral_deg);
    max_dihedral.push_back(s.max_dihedral_deg);
    r.radius_edge_per_tet.push_back(s.radius_edge_ratio);
    r.scaled_jacobian_per_tet.push_back(s.scaled_jacobian);
    r.aspect_ratio_per_tet.push_back(s.aspect_ratio);
  }
  if (!shapes.empty())
    r.tets_min_dihedral_below_10 = static_cast<double>(below_10) / static_cast<double>(shapes.size());
  r.min_dihedral_deg = summarize(r.min_dihedral_per_tet);
  r.max_dihedral_deg = summarize(std::move(max_dihedral));
  r.radius_edge_ratio = summarize(r.radius_edge_per_tet);
  r.scaled_jacobian = summarize(r.scaled_jacobian_per_tet);
  r.aspect_ratio = summarize(r.aspect_ratio_per_tet);
  r.worst_tets = worst_tets(mesh, shapes, worst_tet_count);
  if (mesh.quadratic()) r.quadratic = quadratic_quality(mesh, shapes);
  return r;
}

Json to_json(const TetQualityReport& report) {
  Json regions = Json::object();
  for (const auto& [region, count] : report.tets_per_region) regions[std::to_string(region)] = count;
  Json worst = Json::array();
  for (const WorstTet& w : report.worst_tets) worst.push_back(worst_tet_json(w));
  Json json = {{"points", report.points},
          {"tetrahedra", report.tetrahedra},
          {"volume", json_number(report.volume)},
          {"inverted_tets", report.inverted_tets},
          {"min_dihedral_deg", json_distribution(report.min_dihedral_deg)},
          {"max_dihedral_deg", json_distribution(report.max_dihedral_deg)},
          {"radius_edge_ratio", json_distribution(report.radius_edge_ratio)},
          {"tets_min_dihedral_below_10", report.tets_min_dihedral_below_10},
          {"tets_per_region", regions},
          {"scaled_jacobian", json_distribution(report.scaled_jacobian)},
          {"aspect_ratio", json_distribution(report.aspect_ratio)},
          {"worst_tets", worst}};
  if (report.quadratic)
    json["quadratic"] = {{"min_scaled_jacobian", json_distribution(report.quadratic->min_scaled_jacobian)},
                         {"nonpositive_jacobian_tets", report.quadratic->nonpositive_jacobian_tets},
                         {"curved_tets", report.quadratic->curved_tets}};
  return json;
}

}  // namespace meshprep
