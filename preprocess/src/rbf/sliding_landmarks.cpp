#include "meshprep/preprocess/rbf/sliding_landmarks.h"

#include "rbf/collapse_energy_block.h"

#include "meshprep/core/errors.h"
#include "meshprep/preprocess/rbf/thin_plate_spline.h"

#include <Eigen/QR>

#include <algorithm>
#include <string>

namespace meshprep {
namespace {

using Eigen::Index;

Eigen::MatrixX3d as_rows(const std::vector<Vec3>& points) {
  Eigen::MatrixX3d rows(static_cast<Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i) rows.row(static_cast<Index>(i)) = points[i].transpose();
  return rows;
}

void check_index(std::size_t index, std::size_t size, const char* who) {
  if (index >= size)
    throw InvalidInput(std::string(who) + ": index " + std::to_string(index) + " out of range (" +
                       std::to_string(size) + " points)");
}

}  // namespace

SlidingLandmarks relax_sliding_landmarks(const std::vector<Vec3>& source, const std::vector<Vec3>& target,
                                         const std::vector<std::size_t>& sliding,
                                         const std::vector<Vec3>& directions) {
  constexpr const char* who = "relax_sliding_landmarks";
  if (target.size() != source.size()) throw InvalidInput(std::string(who) + ": source and target sizes differ");
  if (directions.size() != sliding.size())
    throw InvalidInput(std::string(who) + ": one direction per sliding landmark needed");
  for (const std::size_t i : sliding) check_index(i, source.size(), who);

  const Eigen::MatrixXd energy = volume_spline_energy_matrix(source);
  const Eigen::MatrixX3d y0 = as_rows(target);
  const Eigen::MatrixX3d energy_y0 = energy * y0;
  const Index k = static_cast<Index>(sliding.size());
  // U^T L^-1 U and U^T L^-1 Y0 with L^-1 = blockdiag(E, E, E): the x, y, z blocks add up.
  Eigen::MatrixXd normal_matrix(k, k);
  Eigen::VectorXd rhs(k);
  for (Index j = 0; j < k; ++j) {
    const std::size_t ij = sliding[static_cast<std::size_t>(j)];
    const Vec3& uj = directions[static_cast<std::size_t>(j)];
    rhs[j] = uj.dot(energy_y0.row(static_cast<Index>(ij)).transpose());
    for (Index l = 0; l < k; ++l) {
      const std::size_t il = sliding[static_cast<std::size_t>(l)];
      normal_matrix(j, l) = uj.dot(directions[static_cast<std::size_t>(l)]) *
                            energy(static_cast<Index>(ij), static_cast<Index>(il));
    }
  }

  SlidingLandmarks result;
  // No sliding landmark: T is empty and J is the energy of the map itself (COD needs a non-empty matrix).
  if (k > 0) result.t = -normal_matrix.completeOrthogonalDecomposition().solve(rhs);
  result.relaxed = target;
  for (Index j = 0; j < k; ++j)
    result.relaxed[sliding[static_cast<std::size_t>(j)]] += result.t[j] * directions[static_cast<std::size_t>(j)];
  const Eigen::MatrixX3d y = as_rows(result.relaxed);
  result.bending_energy = std::max(0.0, (y.transpose() * energy * y).trace());
  return result;
}

CollapseEnergy::CollapseEnergy(const std::vector<Vec3>& centres, std::size_t a, std::size_t b)
    : CollapseEnergy(centres.data(), centres.size(), a, b) {}

CollapseEnergy::CollapseEnergy(const Vec3* centres, std::size_t count, std::size_t a, std::size_t b) {
  constexpr const char* who = "CollapseEnergy";
  check_index(a, count, who);
  check_index(b, count, who);
  if (a == b) throw InvalidInput(std::string(who) + ": the edge's end points are the same index");
  a_ = centres[a];
  b_ = centres[b];
  if (count >= 4 && count <= static_cast<std::size_t>(detail::kMaxBlockCentres)) {
    // The common case (a mesh edge's two 1-rings): only three entries of E, no heap allocation.
    const detail::EnergyBlock block =
        detail::collapse_energy_block(centres, static_cast<int>(count), static_cast<int>(a), static_cast<int>(b));
    e_aa_ = block.aa;
    e_ab_ = block.ab;
    e_bb_ = block.bb;
    return;
  }
  const Eigen::MatrixXd energy = volume_spline_energy_matrix(std::vector<Vec3>(centres, centres + count));
  const Index ia = static_cast<Index>(a), ib = static_cast<Index>(b);
  e_aa_ = energy(ia, ia);
  e_ab_ = energy(ia, ib);
  e_bb_ = energy(ib, ib);
}

double CollapseEnergy::at(double s) const {
  // |d|^2 w^T E w with w = s e_a + (s - 1) e_b.
  const double wa = s, wb = s - 1;
  return (b_ - a_).squaredNorm() * std::max(0.0, wa * wa * e_aa_ + 2 * wa * wb * e_ab_ + wb * wb * e_bb_);
}

double CollapseEnergy::optimal_parameter() const {
  const double curvature = e_aa_ + 2 * e_ab_ + e_bb_;  // (e_a + e_b)^T E (e_a + e_b) >= 0
  if (!(curvature > 1e-12 * (e_aa_ + e_bb_))) return 0.5;
  return std::clamp((e_ab_ + e_bb_) / curvature, 0.0, 1.0);
}

CollapsePoint optimal_collapse_point(const std::vector<Vec3>& centres, std::size_t a, std::size_t b) {
  const CollapseEnergy energy(centres, a, b);
  CollapsePoint result;
  result.s = energy.optimal_parameter();
  result.point = energy.point(result.s);
  result.bending_energy = energy.at(result.s);
  return result;
}

}  // namespace meshprep
