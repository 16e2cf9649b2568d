#include "meshprep/fem/tet_quality.h"
#include "meshprep/quality/json_values.h"

#include "meshprep/core/errors.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <utility>

namespace meshprep {
namespace {

using Json = nlohmann::ordered_json;

constexpr double kDegreesPerRadian = 180.0 / M_PI;

// Outward normals (unnormalised) of the faces opposite p0..p3 of a positively oriented tet. For an
// inverted tet all four point inward, which leaves the angles between them unchanged.
std::array<Vec3, 4> face_normals(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  return {(p2 - p1).cross(p3 - p1), (p3 - p0).cross(p2 - p0), (p1 - p0).cross(p3 - p0),
          (p2 - p0).cross(p1 - p0)};
}

// Every pair of faces meets at one edge (the edge opposite the two other vertices); the interior
// dihedral angle there is pi minus the angle between the outward normals. atan2(|n1 x n2|, n1.n2)
// stays accurate near 0 and pi, where acos of a normalised dot product does not.
std::pair<double, double> dihedral_range_deg(const std::array<Vec3, 4>& normals) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (int k = 0; k < 4; ++k)
    for (int l = k + 1; l < 4; ++l) {
      const double between_normals = std::atan2(normals[k].cross(normals[l]).norm(), normals[k].dot(normals[l]));
      const double dihedral = (M_PI - between_normals) * kDegreesPerRadian;
      lo = std::min(lo, dihedral);
      hi = std::max(hi, dihedral);
    }
  return {lo, hi};
}

double shortest_edge(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  const double squared = std::min({(p1 - p0).squaredNorm(), (p2 - p0).squaredNorm(), (p3 - p0).squaredNorm(),
                                   (p2 - p1).squaredNorm(), (p3 - p1).squaredNorm(), (p3 - p2).squaredNorm()});
  return std::sqrt(squared);
}

// Circumradius R = |a^2 (b x c) + b^2 (c x a) + c^2 (a x b)| / (12 V), a, b, c the edges from p0
// (the circumcentre relative to p0 is that vector over 2 a.(b x c) = 12 V).
double circumradius(const Vec3& a, const Vec3& b, const Vec3& c, double volume) {
  if (volume == 0) return std::numeric_limits<double>::infinity();
  const Vec3 centre = a.squaredNorm() * b.cross(c) + b.squaredNorm() * c.cross(a) + c.squaredNorm() * a.cross(b);
  return centre.norm() / (12.0 * std::abs(volume));
}

void check_structure(const TetMesh& mesh) {
  if (mesh.tet_regions.size() != mesh.tets.size())
    throw InvalidInput("tet mesh: " + std::to_string(mesh.tet_regions.size()) + " region tags for " +
                       std::to_string(mesh.tets.size()) + " tets");
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (const auto v : mesh.tets[t])
      if (v >= mesh.points.size())
        throw InvalidInput("tet mesh: tet " + std::to_string(t) + " references point " + std::to_string(v) +
                           " of " + std::to_string(mesh.points.size()));
}

std::vector<TetShape> tet_shapes(const TetMesh& mesh) {
  std::vector<TetShape> shapes(mesh.tets.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, shapes.size(), 4096), [&](const auto& range) {
    for (std::size_t t = range.begin(); t != range.end(); ++t) {
      const auto& v = mesh.tets[t];
      shapes[t] = tet_shape(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.points[v[3]]);
    }
  });
  return shapes;
}

}  // namespace

TetShape tet_shape(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  const Vec3 a = p1 - p0, b = p2 - p0, c = p3 - p0;
  TetShape s;
  s.volume = a.dot(b.cross(c)) / 6.0;
  std::tie(s.min_dihedral_deg, s.max_dihedral_deg) = dihedral_range_deg(face_normals(p0, p1, p2, p3));
  s.radius_edge_ratio = circumradius(a, b, c, s.volume) / shortest_edge(p0, p1, p2, p3);
  return s;
}

TetQualityReport analyze_tet_quality(const TetMesh& mesh) {
  check_structure(mesh);
  const std::vector<TetShape> shapes = tet_shapes(mesh);
  TetQualityReport r;
  r.points = mesh.points.size();
  r.tetrahedra = mesh.tets.size();
  std::vector<double> max_dihedral;
  max_dihedral.reserve(shapes.size());
  r.min_dihedral_per_tet.reserve(shapes.size());
  r.radius_edge_per_tet.reserve(shapes.size());
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
  }
  if (!shapes.empty())
    r.tets_min_dihedral_below_10 = static_cast<double>(below_10) / static_cast<double>(shapes.size());
  r.min_dihedral_deg = summarize(r.min_dihedral_per_tet);
  r.max_dihedral_deg = summarize(std::move(max_dihedral));
  r.radius_edge_ratio = summarize(r.radius_edge_per_tet);
  return r;
}

Json to_json(const TetQualityReport& report) {
  Json regions = Json::object();
  for (const auto& [region, count] : report.tets_per_region) regions[std::to_string(region)] = count;
  return {{"points", report.points},
          {"tetrahedra", report.tetrahedra},
          {"volume", json_number(report.volume)},
          {"inverted_tets", report.inverted_tets},
          {"min_dihedral_deg", json_distribution(report.min_dihedral_deg)},
          {"max_dihedral_deg", json_distribution(report.max_dihedral_deg)},
          {"radius_edge_ratio", json_distribution(report.radius_edge_ratio)},
          {"tets_min_dihedral_below_10", report.tets_min_dihedral_below_10},
          {"tets_per_region", regions}};
}

}  // namespace meshprep
