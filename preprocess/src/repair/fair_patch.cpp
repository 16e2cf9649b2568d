#include "repair/fair_patch.h"

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cstddef>
#include <unordered_map>

namespace meshprep::detail {

// The unknowns are numbered first (0 .. new - 1), then the rim and its ring as they come. L's
// rows exist for the unknowns and the rim (the ring's are not needed); the rows of L * L for the
// unknowns split into the unknowns' block and a right-hand side from the fixed vertices.
bool fair_patch(std::vector<Vec3>& points, const std::vector<Triangle>& patch, std::uint32_t first_new,
                const std::vector<std::vector<std::uint32_t>>& neighbours) {
  if (points.size() <= first_new) return true;
  const std::size_t unknowns = points.size() - first_new;
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> ring;
  for (const Triangle& t : patch)
    for (int k = 0; k < 3; ++k) {
      ring[t[k]].push_back(t[(k + 1) % 3]);
      ring[t[k]].push_back(t[(k + 2) % 3]);
    }
  std::vector<std::uint32_t> global;  // local index -> vertex
  std::unordered_map<std::uint32_t, std::size_t> local;
  const auto index = [&](std::uint32_t v) {
    const auto [it, added] = local.emplace(v, global.size());
    if (added) global.push_back(v);
    return it->second;
  };
  for (std::uint32_t v = first_new; v < points.size(); ++v) index(v);
  for (auto& [v, around] : ring) {
    if (v < first_new) around.insert(around.end(), neighbours[v].begin(), neighbours[v].end());
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
  }
  std::vector<Eigen::Triplet<double>> entries;
  for (const auto& [v, around] : ring) {
    const std::size_t row = index(v);
    entries.emplace_back(row, row, -1.0);
    for (const std::uint32_t w : around) entries.emplace_back(row, index(w), 1.0 / static_cast<double>(around.size()));
  }
  using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  const auto n = static_cast<Eigen::Index>(global.size());
  RowMatrix laplacian(n, n);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  const RowMatrix bilaplacian = laplacian * laplacian;
  std::vector<Eigen::Triplet<double>> block;
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(static_cast<Eigen::Index>(unknowns), 3);
  for (Eigen::Index row = 0; row < static_cast<Eigen::Index>(unknowns); ++row)
    for (RowMatrix::InnerIterator it(bilaplacian, row); it; ++it) {
      if (it.col() < static_cast<Eigen::Index>(unknowns))
        block.emplace_back(row, it.col(), it.value());
      else
        rhs.row(row) -= it.value() * points[global[static_cast<std::size_t>(it.col())]].transpose();
    }
  Eigen::SparseMatrix<double> system(static_cast<Eigen::Index>(unknowns), static_cast<Eigen::Index>(unknowns));
  system.setFromTriplets(block.begin(), block.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(system);
  if (lu.info() != Eigen::Success) return false;
  const Eigen::MatrixX3d solution = lu.solve(rhs);
  if (lu.info() != Eigen::Success || !solution.allFinite()) return false;
  for (std::size_t i = 0; i < unknowns; ++i) points[first_new + i] = solution.row(static_cast<Eigen::Index>(i)).transpose();
  return true;
}

}  // namespace meshprep::detail
