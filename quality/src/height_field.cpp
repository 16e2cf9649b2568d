#include "meshprep/quality/height_field.h"

namespace meshprep {
namespace {

Vec3 area_normal(const TriangleSoup& surface, const Triangle& t) {
  return (surface.points[t[1]] - surface.points[t[0]]).cross(surface.points[t[2]] - surface.points[t[0]]);
}

}  // namespace

std::optional<Vec3> mean_normal_axis(const TriangleSoup& surface) {
  Vec3 mean_normal = Vec3::Zero();
  for (const Triangle& t : surface.triangles) mean_normal += area_normal(surface, t);
  if (!(mean_normal.norm() > 0)) return std::nullopt;
  int axis = 0;
  mean_normal.cwiseAbs().maxCoeff(&axis);
  return Vec3::Unit(axis) * (mean_normal[axis] > 0 ? 1.0 : -1.0);
}

std::optional<std::size_t> first_fold(const TriangleSoup& surface, const Vec3& up) {
  for (std::size_t f = 0; f < surface.triangles.size(); ++f)
    if (!(area_normal(surface, surface.triangles[f]).dot(up) > 0)) return f;
  return std::nullopt;
}

std::optional<Vec3> height_field_up(const TriangleSoup& surface) {
  const std::optional<Vec3> up = mean_normal_axis(surface);
  if (!up || first_fold(surface, *up)) return std::nullopt;
  return up;
}

}  // namespace meshprep
