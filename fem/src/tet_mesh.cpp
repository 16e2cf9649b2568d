#include "meshprep/fem/tet_mesh.h"

namespace meshprep {

double tet_volume(const TetMesh& mesh, std::size_t t) {
  const auto& v = mesh.tets[t];
  const Vec3& p0 = mesh.points[v[0]];
  return (mesh.points[v[1]] - p0).dot((mesh.points[v[2]] - p0).cross(mesh.points[v[3]] - p0)) / 6.0;
}

}  // namespace meshprep
