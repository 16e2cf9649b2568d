#include "tet_test_meshes.h"

namespace meshprep::test {

TetMesh cube_tets(int n, double size) {
  TetMesh m;
  const double h = size / n;
  auto id = [&](int i, int j, int k) { return static_cast<std::uint32_t>((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) m.points.emplace_back(i * h, j * h, k * h);
  // The six monotone lattice paths from corner (0,0,0) to (1,1,1) of a cell, one tet each.
  const int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& path : paths) {
          int c[3] = {i, j, k};
          Tetrahedron t;
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[path[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          m.tets.push_back(t);
          if (tet_volume(m, m.tets.size() - 1) < 0) std::swap(m.tets.back()[2], m.tets.back()[3]);
          const Vec3 centre = (m.points[t[0]] + m.points[t[1]] + m.points[t[2]] + m.points[t[3]]) / 4.0;
          m.tet_regions.push_back(centre.x() < size / 2 ? 1 : 2);
        }
  // Boundary: two triangles per boundary cell face, outward.
  auto quad = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d, int tag) {
    m.boundary_faces.push_back({a, b, c});
    m.boundary_faces.push_back({a, c, d});
    m.boundary_tags.push_back(tag);
    m.boundary_tags.push_back(tag);
  };
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      quad(id(0, a, b), id(0, a, b + 1), id(0, a + 1, b + 1), id(0, a + 1, b), 1);
      quad(id(n, a, b), id(n, a + 1, b), id(n, a + 1, b + 1), id(n, a, b + 1), 2);
      quad(id(a, 0, b), id(a + 1, 0, b), id(a + 1, 0, b + 1), id(a, 0, b + 1), 3);
      quad(id(a, n, b), id(a, n, b + 1), id(a + 1, n, b + 1), id(a + 1, n, b), 4);
      quad(id(a, b, 0), id(a, b + 1, 0), id(a + 1, b + 1, 0), id(a + 1, b, 0), 5);
      quad(id(a, b, n), id(a + 1, b, n), id(a + 1, b + 1, n), id(a, b + 1, n), 6);
    }
  return m;
}

}  // namespace meshprep::test
