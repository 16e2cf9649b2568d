#include "test_meshes.h"

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace meshprep::test {

TriangleSoup regular_tetrahedron(double edge) {
  // Alternate corners of a cube with side edge / sqrt(2) form a regular tetrahedron.
  const double h = edge / std::sqrt(2.0);
  TriangleSoup s;
  s.points = {{0, 0, 0}, {h, h, 0}, {h, 0, h}, {0, h, h}};
  s.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  return s;
}

TriangleSoup cube(double s) {
  TriangleSoup c;
  for (int i = 0; i < 8; ++i) c.points.push_back(Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1) * s);
  // Two triangles per side, counter-clockwise seen from outside.
  c.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return c;
}

TriangleSoup box(const Vec3& lo, const Vec3& hi) {
  TriangleSoup b = cube();
  for (Vec3& p : b.points) p = lo + p.cwiseProduct(hi - lo);
  return b;
}

TriangleSoup jittered_icosphere(int levels, double amplitude, unsigned seed) {
  TriangleSoup sphere = icosphere(levels);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-amplitude, amplitude);
  for (Vec3& p : sphere.points) {
    const double z = offset(random), y = offset(random), x = offset(random);
    p = (p + Vec3(x, y, z)).normalized();
  }
  return sphere;
}

TriangleSoup icosphere(int levels, double r) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  TriangleSoup s;
  s.points = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
              {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (auto& p : s.points) p = p.normalized() * r;
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
    auto mid = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      s.points.push_back(((s.points[a] + s.points[b]) * 0.5).normalized() * r);
      const auto index = static_cast<std::uint32_t>(s.points.size() - 1);
      midpoint[key] = index;
      return index;
    };
    std::vector<Triangle> finer;
    for (const Triangle& f : s.triangles) {
      const auto ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      finer.insert(finer.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
    }
    s.triangles = std::move(finer);
  }
  return s;
}

TriangleSoup torus(int n, int m, double R, double r) {
  TriangleSoup s;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double u = 2 * M_PI * i / n, v = 2 * M_PI * j / m;
      s.points.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>((i % n) * m + (j % m)); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

TriangleSoup grid(int n, double z0) {
  TriangleSoup s;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) s.points.emplace_back(i, j, z0);
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

TriangleSoup fan_triangulated_polygon(int corners) {
  TriangleSoup s;
  for (int i = 0; i < corners; ++i) {
    const double angle = 2 * M_PI * i / corners;
    s.points.push_back({std::cos(angle), std::sin(angle), 0});
  }
  for (std::uint32_t i = 1; i + 1 < static_cast<std::uint32_t>(corners); ++i) s.triangles.push_back({0, i, i + 1});
  return s;
}

TriangleSoup cylinder_with_fan_caps(int corners) {
  const TriangleSoup cap = fan_triangulated_polygon(corners);
  TriangleSoup s = merged(cap, translated(cap, {0, 0, 1}));
  const auto n = static_cast<std::uint32_t>(corners);
  for (Triangle& t : s.triangles)
    if (t[0] == 0) std::swap(t[1], t[2]);  // the bottom cap faces down
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    s.triangles.push_back({i, j, n + j});
    s.triangles.push_back({i, n + j, n + i});
  }
  return s;
}

TriangleSoup cube_with_cap(double bulge) {
  TriangleSoup soup;
  soup.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1},
                 Vec3(0.5, -bulge / std::sqrt(2.0), 1 + bulge / std::sqrt(2.0))};
  soup.triangles = {{0, 2, 1}, {0, 3, 2},             // bottom
                    {0, 1, 8}, {0, 8, 4}, {1, 5, 8},  // front, fanned from the new vertex 8
                    {4, 8, 5},                        // the cap on the edge
                    {4, 5, 6}, {4, 6, 7},             // top
                    {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  return soup;
}

TriangleSoup translated(TriangleSoup soup, const Vec3& t) {
  for (auto& p : soup.points) p += t;
  return soup;
}

TriangleSoup merged(const TriangleSoup& a, const TriangleSoup& b) {
  TriangleSoup s = a;
  const auto offset = static_cast<std::uint32_t>(a.points.size());
  s.points.insert(s.points.end(), b.points.begin(), b.points.end());
  for (Triangle t : b.triangles) s.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return s;
}

TriangleSoup subdivided_cube(int n) {
  TriangleSoup soup;
  std::map<std::array<int, 3>, std::uint32_t> index;
  const auto vertex = [&](const std::array<int, 3>& p) {
    const auto [it, added] = index.try_emplace(p, static_cast<std::uint32_t>(soup.points.size()));
    if (added) soup.points.emplace_back(p[0], p[1], p[2]);
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (const int side : {0, n})
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const auto corner = [&](int di, int dj) {
            std::array<int, 3> p{};
            p[axis] = side;
            p[(axis + 1) % 3] = i + di;
            p[(axis + 2) % 3] = j + dj;
            return vertex(p);
          };
          // Counter-clockwise in (axis + 1, axis + 2) faces +axis: outward on the far side.
          const std::uint32_t a = corner(0, 0), b = corner(1, 0), c = corner(1, 1), d = corner(0, 1);
          if (side == n) {
            soup.triangles.push_back({a, b, c});
            soup.triangles.push_back({a, c, d});
          } else {
            soup.triangles.push_back({a, c, b});
            soup.triangles.push_back({a, d, c});
          }
        }
  return soup;
}

TriangleSoup thin_wavy_plate(int n, double gap) {
  TriangleSoup s;
  for (int sheet = 0; sheet < 2; ++sheet)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const double x = 3.0 * i / n, y = 3.0 * j / n;
        s.points.emplace_back(x, y, 0.3 * std::sin(3 * x) * std::cos(2 * y) + sheet * gap);
      }
  auto id = [&](int sheet, int i, int j) { return static_cast<std::uint32_t>(sheet * (n + 1) * (n + 1) + j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      s.triangles.push_back({id(0, i, j), id(0, i + 1, j + 1), id(0, i + 1, j)});  // bottom, facing down
      s.triangles.push_back({id(0, i, j), id(0, i, j + 1), id(0, i + 1, j + 1)});
      s.triangles.push_back({id(1, i, j), id(1, i + 1, j), id(1, i + 1, j + 1)});  // top, facing up
      s.triangles.push_back({id(1, i, j), id(1, i + 1, j + 1), id(1, i, j + 1)});
    }
  std::vector<std::pair<int, int>> rim;
  for (int i = 0; i < n; ++i) rim.emplace_back(i, 0);
  for (int j = 0; j < n; ++j) rim.emplace_back(n, j);
  for (int i = n; i > 0; --i) rim.emplace_back(i, n);
  for (int j = n; j > 0; --j) rim.emplace_back(0, j);
  for (std::size_t k = 0; k < rim.size(); ++k) {
    const auto [i0, j0] = rim[k];
    const auto [i1, j1] = rim[(k + 1) % rim.size()];
    s.triangles.push_back({id(0, i0, j0), id(0, i1, j1), id(1, i1, j1)});
    s.triangles.push_back({id(0, i0, j0), id(1, i1, j1), id(1, i0, j0)});
  }
  return s;
}

}  // namespace meshprep::test
