#pragma once
// The per-face metrics the report files hold, in file order (private to the module).

#include "meshprep/core/errors.h"
#include "meshprep/quality/report.h"

#include <string>

namespace meshprep::detail {

/// A double-valued per-face metric: its column / array name and its TriangleShape field.
struct FaceMetric {
  const char* name;
  double TriangleShape::*field;
};

inline constexpr FaceMetric kFaceMetrics[] = {{"radius_ratio", &TriangleShape::radius_ratio},
                                              {"aspect_ratio", &TriangleShape::aspect_ratio},
                                              {"min_angle_deg", &TriangleShape::min_angle_deg},
                                              {"max_angle_deg", &TriangleShape::max_angle_deg},
                                              {"area", &TriangleShape::area}};

/// \throws InvalidInput naming `path` unless the report has one shape per face of `soup`.
inline void require_one_shape_per_face(const std::string& path, const TriangleSoup& soup, const QualityReport& report) {
  if (report.face_shapes.size() != soup.triangles.size())
    throw InvalidInput(path + ": the quality report has " + std::to_string(report.face_shapes.size()) +
                       " face shapes for a mesh of " + std::to_string(soup.triangles.size()) + " faces");
}

}  // namespace meshprep::detail
