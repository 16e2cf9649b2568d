// make_summary: the report's figures formatted once, for the text summary and the HTML page.

#include "report_summary.h"

#include "meshprep/report/number_format.h"

#include <cmath>

namespace meshprep::detail {
namespace {

std::string yes_no(bool b) { return b ? "yes" : "no"; }

SummaryRow check_row(const std::string& label, std::size_t problems, const std::string& value) {
  return {label, value, problems == 0 ? Check::ok : Check::problem};
}

SummarySection counts(const QualityReport& r) {
  return {"Counts",
          {{"vertices", std::to_string(r.vertices) +
                            (r.isolated_vertices ? " (and " + std::to_string(r.isolated_vertices) +
                                                       " isolated, which no face uses)"
                                                 : std::string())},
           {"faces", std::to_string(r.faces)},
           {"edges", std::to_string(r.edges)},
           {"components", std::to_string(r.components)}}};
}

std::string manifold_value(const QualityReport& r) {
  if (r.manifold) return "yes";
  return "no (" + std::to_string(r.non_manifold_edges) + " edges, " +
         std::to_string(r.non_manifold_vertices) + " vertices non-manifold)";
}

std::string closed_value(const QualityReport& r) {
  if (r.closed) return "yes";
  return "no (" + std::to_string(r.border_edges) + " border edges in " + std::to_string(r.boundary_loops) +
         " loops)";
}

std::string euler_genus_value(const QualityReport& r) {
  return std::to_string(r.euler_characteristic) + " / " + (r.genus ? std::to_string(*r.genus) : "-");
}

SummarySection topology(const QualityReport& r) {
  return {"Topology",
          {{"closed", closed_value(r)},
           {"manifold", manifold_value(r)},
           {"oriented", yes_no(r.oriented)},
           {"Euler characteristic / genus", euler_genus_value(r)}}};
}

std::string self_intersections_value(const QualityReport& r) {
  const std::string count = std::to_string(r.self_intersections);
  return r.self_intersections_capped ? "at least " + count + " (capped)" : count;
}

SummarySection problems(const QualityReport& r) {
  return {"Problems",
          {check_row("degenerate faces", r.degenerate_faces, std::to_string(r.degenerate_faces)),
           check_row("duplicate faces", r.duplicate_faces, std::to_string(r.duplicate_faces)),
           check_row("self-intersections (face pairs)", r.self_intersections, self_intersections_value(r))}};
}

SummarySection geometry(const QualityReport& r) {
  return {"Geometry",
          {{"area", format_figure(r.area)},
           {"volume", r.volume ? format_figure(*r.volume) : "- (not closed and oriented)"},
           {"bbox diagonal", format_figure(r.bbox_diagonal)}}};
}

std::vector<std::string> distribution_row(const std::string& label, const Distribution& d) {
  return {label,
          format_figure(d.min),
          format_figure(d.mean),
          format_figure(d.p5),
          format_figure(d.p50),
          format_figure(d.p95),
          format_figure(d.max)};
}

SummaryTable face_shape(const QualityReport& r) {
  return {{"face shape", "min", "mean", "p5", "p50", "p95", "max"},
          {distribution_row("radius ratio", r.radius_ratio),
           distribution_row("aspect ratio", r.aspect_ratio),
           distribution_row("min angle (deg)", r.min_angle_deg),
           distribution_row("max angle (deg)", r.max_angle_deg),
           distribution_row("face area", r.area_distribution)}};
}

SummarySection shape_fractions(const QualityReport& r) {
  return {"Faces beyond FEM-grade thresholds",
          {{"min angle < 20 deg", format_percent(r.faces_min_angle_below_20)},
           {"min angle < 10 deg", format_percent(r.faces_min_angle_below_10)},
           {"radius ratio > 2", format_percent(r.faces_radius_ratio_above_2)}}};
}

SummaryTable worst_faces(const QualityReport& r) {
  SummaryTable table{{"worst faces", "radius ratio", "min angle (deg)"}, {}};
  for (const WorstFace& face : r.worst_faces) {
    table.rows.push_back(
        {"face " + std::to_string(face.index), format_figure(face.shape.radius_ratio), format_figure(face.shape.min_angle_deg)});
  }
  return table;
}

// An absolute distance followed by the same distance relative to the reference's bbox diagonal.
std::string distance_value(double relative, double diagonal) {
  return format_scientific(relative * diagonal, 2) + "  (relative " + format_scientific(relative, 2) + ")";
}

std::string volume_change_value(const std::optional<double>& percent) {
  if (!percent) return "- (not both closed)";
  return (*percent > 0 ? "+" : "") + format_number(*percent, 4) + " %";
}

SummarySection reference(const ReferenceComparison& c) {
  return {"Reference: " + c.path,
          {{"Hausdorff distance", format_scientific(c.hausdorff, 2) + "  (relative " +
                                      format_scientific(c.hausdorff_relative, 2) + ")"},
           {"RMS distance", distance_value(c.rms_relative, c.reference_bbox_diagonal)},
           {"mean distance", distance_value(c.mean_relative, c.reference_bbox_diagonal)},
           {"volume change", volume_change_value(c.volume_change_percent)},
           {"samples per direction", std::to_string(c.samples)}}};
}

}  // namespace

std::string format_figure(double v) { return std::isnan(v) ? "-" : format_number(v, 4); }

std::string format_percent(double fraction) {
  return std::isfinite(fraction) ? format_fixed(100 * fraction, 2) + " %" : "-";
}

Summary make_summary(const QualityReport& report) {
  Summary s;
  s.file = report.path.empty() ? "(in-memory mesh)" : report.path;
  s.counts = counts(report);
  s.sections = {topology(report), problems(report), geometry(report)};
  s.face_shape = face_shape(report);
  s.shape_fractions = shape_fractions(report);
  s.worst_faces = worst_faces(report);
  if (report.reference) s.reference = reference(*report.reference);
  return s;
}

}  // namespace meshprep::detail
