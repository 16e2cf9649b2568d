#pragma once
// The residuals of the enhancement's Ceres problem (enhance.h), templated for automatic
// differentiation. Each takes the (u, v) unknowns of a face's three vertices.

#include "enhance/vertex_chart.h"

#include <cmath>

namespace meshprep::detail {

/// The three corners of a face where their unknowns put them.
template <typename T>
void corner_positions(const VertexChart (&charts)[3], const T* qa, const T* qb, const T* qc, T (&x)[3][3]) {
  charts[0].position(qa, x[0]);
  charts[1].position(qb, x[1]);
  charts[2].position(qc, x[2]);
}

/// sqrt(w) (1/eta - 1), eta = 4 sqrt(3) A / (|ab|^2 + |bc|^2 + |ca|^2) the mean ratio of the
/// triangle (1 equilateral, -> 0 degenerate). A is the area signed along `normal` (the face's
/// normal at the start of the round): a step that folds the face over is refused (the functor
/// returns false, and Ceres shrinks its trust region). A face that starts degenerate has no
/// direction to keep; its unsigned area is used.
struct MeanRatioResidual {
  VertexChart charts[3];
  Vec3 normal = Vec3::Zero();
  double sqrt_weight = 1;
  bool signed_area = true;

  template <typename T>
  bool operator()(const T* qa, const T* qb, const T* qc, T* residual) const {
    T x[3][3];
    corner_positions(charts, qa, qb, qc, x);
    T ab[3], ac[3], bc[3];
    for (int i = 0; i < 3; ++i) ab[i] = x[1][i] - x[0][i], ac[i] = x[2][i] - x[0][i], bc[i] = x[2][i] - x[1][i];
    const T cross[3] = {ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0]};
    const T squares = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2] + ac[0] * ac[0] + ac[1] * ac[1] + ac[2] * ac[2] +
                      bc[0] * bc[0] + bc[1] * bc[1] + bc[2] * bc[2];
    T twice_area;
    if (signed_area) {
      twice_area = cross[0] * normal[0] + cross[1] * normal[1] + cross[2] * normal[2];
      if (!(twice_area > T(0))) return false;
    } else {
      using std::sqrt;
      twice_area = sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2] + T(1e-300));
    }
    // 1/eta = squares / (4 sqrt(3) A) = squares / (2 sqrt(3) twice_area).
    residual[0] = sqrt_weight * (squares / (2 * std::sqrt(3.0) * twice_area) - T(1));
    return true;
  }
};

/// sqrt(lambda) n . (centroid - p) / scale: how far the face's centroid is from the reference's
/// tangent plane (point p, unit normal n) at the closest point to where the centroid started.
struct FaceFidelityResidual {
  VertexChart charts[3];
  Vec3 plane_point = Vec3::Zero(), plane_normal = Vec3::Zero();
  double sqrt_weight_over_scale = 1;

  template <typename T>
  bool operator()(const T* qa, const T* qb, const T* qc, T* residual) const {
    T x[3][3];
    corner_positions(charts, qa, qb, qc, x);
    T distance = T(0);
    for (int i = 0; i < 3; ++i) distance += ((x[0][i] + x[1][i] + x[2][i]) / 3.0 - plane_point[i]) * plane_normal[i];
    residual[0] = sqrt_weight_over_scale * distance;
    return true;
  }
};

}  // namespace meshprep::detail
