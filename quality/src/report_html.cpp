// write_html: one self-contained page (inline CSS and SVG, no script, no external resource).

#include "meshprep/quality/report_writers.h"

#include "meshprep/core/atomic_file.h"

#include "number_format.h"
#include "report_summary.h"
#include "svg_histogram.h"

#include <algorithm>
#include <cmath>

namespace meshprep {
namespace {

using detail::xml_escape;

constexpr const char* kStyle = R"(
body { font-family: sans-serif; color: #222; margin: 24px auto; max-width: 1180px; padding: 0 12px; }
h1 { font-size: 22px; margin-bottom: 4px; }
h1 .file { font-family: monospace; font-weight: normal; }
h2 { font-size: 17px; border-bottom: 1px solid #ddd; padding-bottom: 4px; margin-top: 28px; }
.badges { display: flex; flex-wrap: wrap; gap: 8px; list-style: none; padding: 0; margin: 0; }
.badge { border-radius: 6px; padding: 6px 10px; color: #fff; font-size: 14px; }
.badge.pass { background: #2e7d32; } .badge.fail { background: #c62828; }
.badge .value { font-weight: bold; margin-left: 6px; }
.note { color: #666; font-size: 13px; }
.tables { display: flex; flex-wrap: wrap; gap: 12px 28px; align-items: flex-start; }
.tables + .tables { margin-top: 18px; }
table { border-collapse: collapse; font-size: 13px; }
caption { font-weight: bold; text-align: left; padding: 4px 0; white-space: nowrap; }
th, td { padding: 3px 8px; border-bottom: 1px solid #eee; text-align: left; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; }
td.ok { color: #2e7d32; } td.problem { color: #c62828; font-weight: bold; }
.histograms { display: flex; flex-wrap: wrap; gap: 16px; }
footer { margin-top: 28px; color: #888; font-size: 12px; }
)";

// ---- checks ----------------------------------------------------------------------------------

struct Badge {
  std::string name;
  std::string value;  ///< the measured value
  bool pass;
};

std::string count_value(std::size_t n, bool capped = false) { return (capped ? "\u2265 " : "") + std::to_string(n); }

std::vector<Badge> badges(const QualityReport& r) {
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

void write_checks(std::ostream& out, const QualityReport& report) {
  out << "<h2>Checks</h2>\n<ul class=\"badges\">\n";
  for (const Badge& b : badges(report)) {
    out << "<li class=\"badge " << (b.pass ? "pass\">\u2714 " : "fail\">\u2718 ") << xml_escape(b.name)
        << "<span class=\"value\">" << xml_escape(b.value) << "</span></li>\n";
  }
  out << "</ul>\n<p class=\"note\">The last two are FEM-grade shape targets (over the non-degenerate "
         "faces).</p>\n";
}

// ---- summary tables --------------------------------------------------------------------------

const char* check_class(detail::Check check) {
  switch (check) {
    case detail::Check::ok: return " class=\"ok\"";
    case detail::Check::problem: return " class=\"problem\"";
    case detail::Check::none: break;
  }
  return "";
}

void write_section(std::ostream& out, const detail::SummarySection& section) {
  out << "<table>\n<caption>" << xml_escape(section.title) << "</caption>\n";
  for (const detail::SummaryRow& row : section.rows) {
    out << "<tr><th>" << xml_escape(row.label) << "</th><td" << check_class(row.check) << ">" << xml_escape(row.value)
        << "</td></tr>\n";
  }
  out << "</table>\n";
}

// A table of numbers: the first column holds labels, the others right-aligned figures.
void write_table_row(std::ostream& out, const std::vector<std::string>& cells, const char* cell) {
  out << "<tr><" << cell << '>' << xml_escape(cells[0]) << "</" << cell << '>';
  for (std::size_t c = 1; c < cells.size(); ++c)
    out << '<' << cell << " class=\"num\">" << xml_escape(cells[c]) << "</" << cell << '>';
  out << "</tr>\n";
}

void write_table(std::ostream& out, const detail::SummaryTable& table) {
  out << "<table>\n";
  write_table_row(out, table.header, "th");
  for (const auto& row : table.rows) write_table_row(out, row, "td");
  out << "</table>\n";
}

void write_summary(std::ostream& out, const detail::Summary& summary) {
  out << "<h2>Summary</h2>\n<div class=\"tables\">\n";
  write_section(out, summary.counts);
  for (const detail::SummarySection& section : summary.sections) write_section(out, section);
  write_section(out, summary.shape_fractions);
  if (summary.reference) write_section(out, *summary.reference);
  out << "</div>\n<div class=\"tables\">\n";
  write_table(out, summary.face_shape);
  if (!summary.worst_faces.rows.empty()) write_table(out, summary.worst_faces);
  out << "</div>\n";
}

// ---- histograms ------------------------------------------------------------------------------

std::vector<double> face_values(const QualityReport& report, double TriangleShape::*field) {
  std::vector<double> values;
  values.reserve(report.face_shapes.size());
  for (const TriangleShape& shape : report.face_shapes) values.push_back(shape.*field);
  return values;
}

std::vector<detail::HistogramMarker> percentile_markers(const Distribution& d) {
  return {{"p5", d.p5}, {"p50", d.p50}, {"p95", d.p95}};
}

// Ratios are 1 for an equilateral triangle; everything beyond 5 (degenerate faces included) is
// gathered in the overflow bar.
detail::HistogramOptions ratio_histogram(const std::string& title, const std::string& x_label, const Distribution& d) {
  detail::HistogramOptions o;
  o.title = title;
  o.x_label = x_label;
  o.lo = 1;
  o.hi = 5;
  o.overflow = true;
  o.markers = percentile_markers(d);
  return o;
}

detail::HistogramOptions angle_histogram(const std::string& title, double lo, double hi, const Distribution& d) {
  detail::HistogramOptions o;
  o.title = title;
  o.x_label = "degrees";
  o.lo = lo;
  o.hi = hi;
  o.bins = 60;
  o.markers = percentile_markers(d);
  return o;
}

// Areas from 0 to twice the 95th percentile, larger ones in an overflow bar: a few huge faces
// (common after decimation) would otherwise squeeze every other face into the first bin.
detail::HistogramOptions area_histogram(const std::vector<double>& areas, const Distribution& d) {
  double largest = 0;
  for (double a : areas)
    if (std::isfinite(a)) largest = std::max(largest, a);
  detail::HistogramOptions o;
  o.title = "Face area";
  o.x_label = "area";
  const double clip = std::isfinite(d.p95) && d.p95 > 0 ? 2 * d.p95 : largest;
  o.hi = clip > 0 ? std::min(clip, largest) : 1;
  o.overflow = largest > o.hi;
  o.markers = percentile_markers(d);
  return o;
}

void write_histograms(std::ostream& out, const QualityReport& r) {
  const std::vector<double> areas = face_values(r, &TriangleShape::area);
  out << "<h2>Histograms</h2>\n<div class=\"histograms\">\n"
      << detail::svg_histogram(face_values(r, &TriangleShape::radius_ratio),
                               ratio_histogram("Radius ratio", "R / (2 r)   (1 = equilateral)", r.radius_ratio))
      << detail::svg_histogram(face_values(r, &TriangleShape::aspect_ratio),
                               ratio_histogram("Aspect ratio", "l_max (a+b+c) / (4 \u221a3 A)   (1 = equilateral)",
                                               r.aspect_ratio))
      << detail::svg_histogram(face_values(r, &TriangleShape::min_angle_deg),
                               angle_histogram("Minimum angle", 0, 60, r.min_angle_deg))
      << detail::svg_histogram(face_values(r, &TriangleShape::max_angle_deg),
                               angle_histogram("Maximum angle", 60, 180, r.max_angle_deg))
      << detail::svg_histogram(areas, area_histogram(areas, r.area_distribution)) << "</div>\n";
}

// ---- page ------------------------------------------------------------------------------------

void write_page(std::ostream& out, const QualityReport& report) {
  const detail::Summary summary = detail::make_summary(report);
  const std::string file = xml_escape(summary.file);
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<title>Mesh quality: " << file << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n"
      << "<h1>Mesh quality: <span class=\"file\">" << file << "</span></h1>\n";
  write_checks(out, report);
  write_summary(out, summary);
  write_histograms(out, report);
  out << "<footer>meshprep quality report; analysis took " << detail::format_fixed(report.time_seconds, 3)
      << " s.</footer>\n</body>\n</html>\n";
}

}  // namespace

void write_html(const std::string& path, const QualityReport& report) {
  write_file_atomically(path, [&](std::ostream& out) { write_page(out, report); });
}

}  // namespace meshprep
