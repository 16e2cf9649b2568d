// to_json: the machine interface of the quality report. Key names and order are stable.

#include "meshprep/quality/json_values.h"
#include "meshprep/report/report_writers.h"

#include <cmath>

namespace meshprep {
namespace {

using Json = nlohmann::ordered_json;

Json optional_number(const std::optional<double>& v) { return v ? json_number(*v) : Json(nullptr); }

Json point(const Vec3& p) { return Json::array({json_number(p.x()), json_number(p.y()), json_number(p.z())}); }

Json intersecting_pairs(const QualityReport& report) {
  Json pairs = Json::array();
  for (const auto& [a, b] : report.self_intersecting_pairs) pairs.push_back(Json::array({a, b}));
  return pairs;
}

Json worst_faces(const QualityReport& report) {
  Json faces = Json::array();
  for (const WorstFace& face : report.worst_faces) {
    const TriangleShape& s = face.shape;
    faces.push_back({{"index", face.index},
                     {"radius_ratio", json_number(s.radius_ratio)},
                     {"aspect_ratio", json_number(s.aspect_ratio)},
                     {"min_angle_deg", json_number(s.min_angle_deg)},
                     {"max_angle_deg", json_number(s.max_angle_deg)},
                     {"area", json_number(s.area)}});
  }
  return faces;
}

Json reference(const ReferenceComparison& r) {
  return {{"file", r.path},
          {"hausdorff", json_number(r.hausdorff)},
          {"hausdorff_relative", json_number(r.hausdorff_relative)},
          {"rms_relative", json_number(r.rms_relative)},
          {"mean_relative", json_number(r.mean_relative)},
          {"reference_bbox_diagonal", json_number(r.reference_bbox_diagonal)},
          {"volume_change_percent", optional_number(r.volume_change_percent)},
          {"samples", r.samples}};
}

}  // namespace

nlohmann::ordered_json to_json(const QualityReport& report) {
  Json j;
  j["file"] = report.path;
  j["vertices"] = report.vertices;
  j["isolated_vertices"] = report.isolated_vertices;
  j["faces"] = report.faces;
  j["edges"] = report.edges;
  j["components"] = report.components;
  j["border_edges"] = report.border_edges;
  j["boundary_loops"] = report.boundary_loops;
  j["non_manifold_edges"] = report.non_manifold_edges;
  j["non_manifold_vertices"] = report.non_manifold_vertices;
  j["closed"] = report.closed;
  j["manifold"] = report.manifold;
  j["oriented"] = report.oriented;
  j["euler_characteristic"] = report.euler_characteristic;
  j["genus"] = report.genus ? Json(*report.genus) : Json(nullptr);
  j["degenerate_faces"] = report.degenerate_faces;
  j["duplicate_faces"] = report.duplicate_faces;
  j["self_intersections"] = report.self_intersections;
  j["self_intersections_capped"] = report.self_intersections_capped;
  j["self_intersecting_pairs"] = intersecting_pairs(report);
  j["area"] = json_number(report.area);
  j["volume"] = optional_number(report.volume);
  j["bbox_diagonal"] = json_number(report.bbox_diagonal);
  j["bbox_min"] = point(report.bbox_min);
  j["bbox_max"] = point(report.bbox_max);
  j["radius_ratio"] = json_distribution(report.radius_ratio);
  j["aspect_ratio"] = json_distribution(report.aspect_ratio);
  j["min_angle_deg"] = json_distribution(report.min_angle_deg);
  j["max_angle_deg"] = json_distribution(report.max_angle_deg);
  j["face_area"] = json_distribution(report.area_distribution);
  j["faces_min_angle_below_20"] = json_number(report.faces_min_angle_below_20);
  j["faces_min_angle_below_10"] = json_number(report.faces_min_angle_below_10);
  j["faces_radius_ratio_above_2"] = json_number(report.faces_radius_ratio_above_2);
  j["worst_faces"] = worst_faces(report);
  if (report.reference) j["reference"] = reference(*report.reference);
  j["time_seconds"] = json_number(report.time_seconds);
  return j;
}

}  // namespace meshprep
