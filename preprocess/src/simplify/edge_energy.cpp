#include "simplify/edge_energy.h"

#include "shared/edge_lengths.h"

#include "meshprep/core/errors.h"
#include "meshprep/preprocess/rbf/sliding_landmarks.h"

#include <algorithm>
#include <cmath>

namespace meshprep::detail {
namespace {

using VertexHandle = TriMesh::VertexHandle;
using EdgeHandle = TriMesh::EdgeHandle;
using HalfedgeHandle = TriMesh::HalfedgeHandle;

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

EdgeEnergy edge_energy(RingUnion& rings, TriMesh::VertexHandle a, TriMesh::VertexHandle b, std::vector<Vec3>* neighbourhood) {
  Vec3 centres[kMaxBlockCentres];
  const int n = rings.gather(a, b, centres);
  EdgeEnergy result;
  if (n < 4) return result;
  try {
    const CollapseEnergy energy(centres, static_cast<std::size_t>(n), 0, 1);
    const double s = energy.optimal_parameter();
    result.energy = energy.at(s);
    result.point = energy.point(s);
  } catch (const Error&) {
    return result;
  }
  if (neighbourhood) neighbourhood->assign(centres, centres + n);
  return result;
}

CollapseScales measure_scales(const TriMesh& mesh, CollapseCost cost) {
  CollapseScales scales;
  scales.edge_length = median_edge_length(mesh);
  if (!(scales.edge_length > 0)) throw InvalidInput("the mesh's edges have zero length");
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (const VertexHandle v : mesh.vertices()) {
    low = low.cwiseMin(to_eigen(mesh.point(v)));
    high = high.cwiseMax(to_eigen(mesh.point(v)));
  }
  scales.diagonal = (high - low).norm();
  if (cost != CollapseCost::Bending) return scales;
  // J / |e| on about 2000 evenly spread edges: enough for a stable median.
  const std::size_t stride = std::max<std::size_t>(1, mesh.n_edges() / 2000);
  std::vector<double> ratios;
  RingUnion rings(mesh);
  for (std::size_t i = 0; i < mesh.n_edges(); i += stride) {
    const EdgeHandle e(static_cast<int>(i));
    const HalfedgeHandle h = mesh.halfedge_handle(e, 0);
    const double length = mesh.calc_edge_length(e);
    const EdgeEnergy energy = edge_energy(rings, mesh.from_vertex_handle(h), mesh.to_vertex_handle(h), nullptr);
    if (std::isfinite(energy.energy) && length > 0) ratios.push_back(energy.energy / length);
  }
  const double typical = median(std::move(ratios));
  scales.energy_per_length = typical > 0 ? typical : 1.0;
  return scales;
}

}  // namespace meshprep::detail
