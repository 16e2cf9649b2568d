#include "meshprep/core/finite_points.h"

#include "meshprep/core/errors.h"

#include <sstream>

namespace meshprep {
namespace {

[[noreturn]] void fail(const std::string& stage, std::size_t vertex, const Vec3& p) {
  std::ostringstream message;
  message << stage << " failed: vertex " << vertex << " has a non-finite coordinate (" << p.x() << ", " << p.y()
          << ", " << p.z() << ")";
  throw SolverError(message.str());
}

}  // namespace

void require_finite_points(const std::vector<Vec3>& points, const std::string& stage) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!points[i].allFinite()) fail(stage, i, points[i]);
}

void require_finite_points(const TriMesh& mesh, const std::string& stage) {
  for (const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    const Vec3 point(p[0], p[1], p[2]);
    if (!point.allFinite()) fail(stage, static_cast<std::size_t>(v.idx()), point);
  }
}

}  // namespace meshprep
