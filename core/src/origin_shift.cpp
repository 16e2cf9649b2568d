#include "meshprep/core/origin_shift.h"

#include <cmath>

namespace meshprep {

Vec3 origin_shift(const PointSpan& points) {
  Vec3 shift = Vec3::Zero();
  if (points.empty()) return shift;
  Vec3 low = points[0], high = points[0];
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 p = points[i];
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  for (int k = 0; k < 3; ++k) {
    const double centre = low[k] + (high[k] - low[k]) / 2;
    if (std::abs(centre) > high[k] - low[k]) shift[k] = centre;
  }
  return shift;
}

namespace {

std::vector<Vec3> points_of(const TriMesh& mesh) {
  std::vector<Vec3> points;
  points.reserve(mesh.n_vertices());
  for (const auto v : mesh.vertices()) points.push_back(to_eigen(mesh.point(v)));
  return points;
}

void move_all(TriMesh& mesh, const Vec3& by) {
  const OpenMesh::Vec3d offset = to_openmesh(by);
  for (const auto v : mesh.all_vertices()) mesh.point(v) += offset;
}

}  // namespace

ShiftedToOrigin::ShiftedToOrigin(TriMesh& mesh) : mesh_(mesh), shift_(origin_shift(points_of(mesh))) {
  if (!shift_.isZero()) move_all(mesh_, -shift_);
}

ShiftedToOrigin::~ShiftedToOrigin() {
  if (!shift_.isZero()) move_all(mesh_, shift_);
}

TriangleSoup ShiftedToOrigin::moved(const TriangleSoup& soup) const {
  TriangleSoup copy = soup;
  for (Vec3& p : copy.points) p -= shift_;
  return copy;
}

}  // namespace meshprep
