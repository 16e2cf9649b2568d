// write_html: one self-contained page (inline CSS, SVG and PNG, no script, no external resource).

#include "meshprep/report/report_writers.h"

#include "meshprep/core/atomic_file.h"
#include "meshprep/report/html_report.h"
#include "meshprep/report/number_format.h"
#include "meshprep/report/surface_picture.h"

#include "report_summary.h"

#include <algorithm>
#include <cmath>

namespace meshprep {
namespace {

using html::escape;

void write_checks(std::ostream& out, const QualityReport& report) {
  out << "<h2>Checks</h2>\n"
      << html::badges(html::surface_badges(report))
      << "<p class=\"note\">The last two are FEM-grade shape targets (over the non-degenerate faces).</p>\n";
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
  out << "<table>\n<caption>" << escape(section.title) << "</caption>\n";
  for (const detail::SummaryRow& row : section.rows) {
    out << "<tr><th>" << escape(row.label) << "</th><td" << check_class(row.check) << ">" << escape(row.value)
        << "</td></tr>\n";
  }
  out << "</table>\n";
}

// A table of numbers: the first column holds labels, the others right-aligned figures.
void write_table_row(std::ostream& out, const std::vector<std::string>& cells, const char* cell) {
  out << "<tr><" << cell << '>' << escape(cells[0]) << "</" << cell << '>';
  for (std::size_t c = 1; c < cells.size(); ++c)
    out << '<' << cell << " class=\"num\">" << escape(cells[c]) << "</" << cell << '>';
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

html::HistogramOptions aspect_histogram(const Distribution& d) {
  html::HistogramOptions o;
  o.title = "Aspect ratio";
  o.x_label = "l_max (a+b+c) / (4 \u221a3 A)   (1 = equilateral)";
  o.lo = 1;
  o.hi = 5;
  o.overflow = true;
  o.markers = html::percentile_markers(d);
  return o;
}

html::HistogramOptions max_angle_histogram(const Distribution& d) {
  html::HistogramOptions o;
  o.title = "Maximum angle";
  o.x_label = "degrees";
  o.lo = 60;
  o.hi = 180;
  o.bins = 60;
  o.markers = html::percentile_markers(d);
  return o;
}

// Areas from 0 to twice the 95th percentile, larger ones in an overflow bar: a few huge faces
// (common after decimation) would otherwise squeeze every other face into the first bin.
html::HistogramOptions area_histogram(const std::vector<double>& areas, const Distribution& d) {
  double largest = 0;
  for (double a : areas)
    if (std::isfinite(a)) largest = std::max(largest, a);
  html::HistogramOptions o;
  o.title = "Face area";
  o.x_label = "area";
  const double clip = std::isfinite(d.p95) && d.p95 > 0 ? 2 * d.p95 : largest;
  o.hi = clip > 0 ? std::min(clip, largest) : 1;
  o.overflow = largest > o.hi;
  o.markers = html::percentile_markers(d);
  return o;
}

void write_histograms(std::ostream& out, const QualityReport& r) {
  const std::vector<double> areas = face_values(r, &TriangleShape::area);
  out << "<h2>Histograms</h2>\n<div class=\"histograms\">\n"
      << html::radius_ratio_histogram(r, "Radius ratio")
      << html::svg_histogram(face_values(r, &TriangleShape::aspect_ratio), aspect_histogram(r.aspect_ratio))
      << html::min_angle_histogram(r, "Minimum angle")
      << html::svg_histogram(face_values(r, &TriangleShape::max_angle_deg), max_angle_histogram(r.max_angle_deg))
      << html::svg_histogram(areas, area_histogram(areas, r.area_distribution)) << "</div>\n";
}

// ---- page ------------------------------------------------------------------------------------

void write_page(std::ostream& out, const TriangleSoup& soup, const QualityReport& report) {
  const detail::Summary summary = detail::make_summary(report);
  out << html::page_start("Mesh quality: " + summary.file) << "<h1>Mesh quality: <span class=\"file\">"
      << escape(summary.file) << "</span></h1>\n";
  write_checks(out, report);
  out << "<h2>The surface</h2>\n" << surface_picture_html(soup, report);
  write_summary(out, summary);
  write_histograms(out, report);
  out << html::page_end("meshprep quality report; analysis took " + format_fixed(report.time_seconds, 3) + " s.");
}

}  // namespace

void write_html(const std::string& path, const TriangleSoup& soup, const QualityReport& report) {
  write_file_atomically(path, [&](std::ostream& out) { write_page(out, soup, report); });
}

}  // namespace meshprep
