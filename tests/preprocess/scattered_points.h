#pragma once
// Scattered samples of height fields for the reconstruction tests.

#include "meshprep/core/mesh.h"

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace meshprep::test {

// Deterministic scattered (x, y) in [-1, 1]^2 (a low-discrepancy sequence, no two equal).
inline std::vector<Eigen::Vector2d> scattered(int count) {
  std::vector<Eigen::Vector2d> sites;
  for (int i = 0; i < count; ++i)
    sites.emplace_back(2 * std::fmod(0.5 + i * 0.7548776662466927, 1.0) - 1, 2 * std::fmod(0.5 + i * 0.5698402909980532, 1.0) - 1);
  return sites;
}

template <class Height>
std::vector<Vec3> sample(int count, Height height, const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
  std::vector<Vec3> points;
  for (const Eigen::Vector2d& s : scattered(count)) points.push_back(rotation * Vec3(s.x(), s.y(), height(s.x(), s.y())));
  return points;
}

}  // namespace meshprep::test
