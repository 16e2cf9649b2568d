// The shared pieces of the HTML reports: page frame and style, badges, the per-face histograms.

#include "meshprep/report/html_report.h"

#include "meshprep/report/number_format.h"

#include "report_summary.h"

namespace meshprep::html {
namespace {

constexpr const char* kStyle = R"(
body { font-family: sans-serif; color: #222; margin: 24px auto; max-width: 1180px; padding: 0 12px; }
h1 { font-size: 22px; margin-bottom: 4px; }
h1 .file { font-family: monospace; font-weight: normal; }
h2 { font-size: 17px; border-bottom: 1px solid #ddd; padding-bottom: 4px; margin-top: 28px; }
.badges { display: flex; flex-wrap: wrap; gap: 8px; list-style: none; padding: 0; margin: 0; }
.badge { border-radius: 6px; padding: 6px 10px; color: #fff; font-size: 14px; }
.badge.pass { background: #2e7d32; } .badge.fail { background: #c62828; }
.badge .value { font-weight: bold; margin-left: 6px; }
.verdict { border-radius: 6px; padding: 8px 12px; color: #fff; font-size: 16px; font-weight: bold; }
.verdict.pass { background: #2e7d32; } .verdict.fail { background: #c62828; }
.note { color: #666; font-size: 13px; }
.tables { display: flex; flex-wrap: wrap; gap: 12px 28px; align-items: flex-start; }
.tables + .tables { margin-top: 18px; }
table { border-collapse: collapse; font-size: 13px; }
caption { font-weight: bold; text-align: left; padding: 4px 0; white-space: nowrap; }
th, td { padding: 3px 8px; border-bottom: 1px solid #eee; text-align: left; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; }
td.ok { color: #2e7d32; } td.problem { color: #c62828; font-weight: bold; }
.histograms { display: flex; flex-wrap: wrap; gap: 16px; }
figure { margin: 0; } figcaption { font-size: 13px; color: #444; margin-top: 4px; }
.pictures { display: flex; flex-wrap: wrap; gap: 16px; align-items: flex-start; }
.pictures img { border: 1px solid #ddd; max-width: 100%; height: auto; }
.patch-key { display: inline-block; margin: 2px 12px 2px 0; }
.swatch { display: inline-block; width: 12px; height: 12px; margin-right: 4px; vertical-align: middle; }
pre { background: #f6f6f6; padding: 8px; font-size: 12px; overflow-x: auto; }
footer { margin-top: 28px; color: #888; font-size: 12px; }
)";

std::string count_value(std::size_t n, bool capped = false) { return (capped ? "\u2265 " : "") + std::to_string(n); }

std::vector<double> face_values(const QualityReport& report, double TriangleShape::*field) {
  std::vector<double> values;
  values.reserve(report.face_shapes.size());
  for (const TriangleShape& shape : report.face_shapes) values.push_back(shape.*field);
  return values;
}

}  // namespace

std::string page_start(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         escape(title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
}

std::string page_end(const std::string& footer) { return "<footer>" + escape(footer) + "</footer>\n</body>\n</html>\n"; }

std::string badges(const std::vector<Badge>& list) {
  std::string out = "<ul class=\"badges\">\n";
  for (const Badge& b : list)
    out += std::string("<li class=\"badge ") + (b.pass ? "pass\">\u2714 " : "fail\">\u2718 ") + escape(b.name) +
           "<span class=\"value\">" + escape(b.value) + "</span></li>\n";
  return out + "</ul>\n";
}

std::vector<Badge> surface_badges(const QualityReport& r) {
  const double p95 = r.radius_ratio.p95;
  return {
      {"closed", r.closed ? "yes" : std::to_string(r.border_edges) + " border edges", r.closed},
      {"manifold", r.manifold ? "yes" : std::to_string(r.non_manifold_edges) + " edges, " +
                                            std::to_string(r.non_manifold_vertices) + " vertices non-manifold",
       r.manifold},
      {"consistently oriented", r.oriented ? "yes" : "no", r.oriented},
      {"no degenerate faces", count_value(r.degenerate_faces), r.degenerate_faces == 0},
      {"no duplicate faces", count_value(r.duplicate_faces), r.duplicate_faces == 0},
      {"no self-intersections", count_value(r.self_intersections, r.self_intersections_capped),
       r.self_intersections == 0},
      {"min angle < 20\u00b0 on \u2264 5 % of faces", detail::format_percent(r.faces_min_angle_below_20),
       r.faces_min_angle_below_20 <= 0.05},
      {"radius ratio p95 \u2264 2", detail::format_figure(p95), p95 <= 2},  // false for NaN (no valid face)
  };
}

std::vector<HistogramMarker> percentile_markers(const Distribution& d) {
  return {{"p5", d.p5}, {"p50", d.p50}, {"p95", d.p95}};
}

// Ratios are 1 for an equilateral triangle; everything beyond 5 (degenerate faces included) is
// gathered in the overflow bar.
std::string radius_ratio_histogram(const QualityReport& report, const std::string& title) {
  HistogramOptions o;
  o.title = title;
  o.x_label = "R / (2 r)   (1 = equilateral)";
  o.lo = 1;
  o.hi = 5;
  o.overflow = true;
  o.markers = percentile_markers(report.radius_ratio);
  return svg_histogram(face_values(report, &TriangleShape::radius_ratio), o);
}

std::string min_angle_histogram(const QualityReport& report, const std::string& title) {
  HistogramOptions o;
  o.title = title;
  o.x_label = "degrees";
  o.lo = 0;
  o.hi = 60;
  o.bins = 60;
  o.markers = percentile_markers(report.min_angle_deg);
  return svg_histogram(face_values(report, &TriangleShape::min_angle_deg), o);
}

}  // namespace meshprep::html
