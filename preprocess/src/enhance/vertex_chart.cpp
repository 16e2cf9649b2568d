#include "enhance/vertex_chart.h"

#include <Eigen/QR>

namespace meshprep::detail {

VertexChart surface_chart(const Vec3& origin, const Vec3& normal, const std::vector<Vec3>& neighbours) {
  VertexChart chart;
  chart.origin = origin;
  chart.normal = normal;
  const Vec3 helper = std::abs(normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  chart.t1 = normal.cross(helper).normalized();
  chart.t2 = normal.cross(chart.t1);
  if (neighbours.size() < 5) return chart;
  // Height w over the tangent plane: w = c0 u^2 + c1 uv + c2 v^2 + c3 u + c4 v (through the
  // vertex, so no constant: the vertex itself stays on its chart at (0, 0)).
  Eigen::MatrixXd a(static_cast<Eigen::Index>(neighbours.size()), 5);
  Eigen::VectorXd w(a.rows());
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    const Vec3 d = neighbours[static_cast<std::size_t>(i)] - origin;
    const double u = d.dot(chart.t1), v = d.dot(chart.t2);
    a.row(i) << u * u, u * v, v * v, u, v;
    w(i) = d.dot(normal);
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  if (qr.rank() < 5) return chart;
  const Eigen::VectorXd c = qr.solve(w);
  for (int i = 0; i < 5; ++i) chart.height[i] = c(i);
  return chart;
}

VertexChart line_chart(const Vec3& origin, const Vec3& direction) {
  VertexChart chart;
  chart.origin = origin;
  chart.t1 = direction;
  return chart;
}

VertexChart fixed_chart(const Vec3& origin) {
  VertexChart chart;
  chart.origin = origin;
  return chart;
}

VertexChart in_units_of(VertexChart chart, double length) {
  chart.t1 *= length;
  chart.t2 *= length;
  for (int i = 0; i < 3; ++i) chart.height[i] *= length * length;  // the quadratic terms
  for (int i = 3; i < 5; ++i) chart.height[i] *= length;           // the linear ones
  return chart;
}

}  // namespace meshprep::detail
