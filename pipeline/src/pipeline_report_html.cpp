// report.html: one self-contained page for a whole run (inline CSS, SVG and PNG; no script).

#include "meshprep/pipeline/pipeline_outputs.h"

#include "meshprep/quality/html_report.h"
#include "meshprep/quality/number_format.h"
#include "meshprep/quality/surface_picture.h"

#include <cmath>
#include <sstream>

namespace meshprep {
namespace {

using html::escape;

// FEM codes commonly warn below this smallest dihedral angle; shown as a check, not a gate.
constexpr double kDihedralWarningDeg = 5;

std::string optional_scientific(const std::optional<double>& v) { return v ? format_scientific(*v, 2) : "-"; }

std::string percent(double fraction) { return std::isfinite(fraction) ? format_fixed(100 * fraction, 2) + " %" : "-"; }

std::string figure(double v) { return std::isfinite(v) ? format_number(v, 4) : "-"; }

std::string row(const std::vector<std::string>& cells, const char* tag = "td") {
  std::string out = "<tr>";
  for (std::size_t i = 0; i < cells.size(); ++i)
    out += std::string("<") + tag + (i > 0 && i + 1 < cells.size() ? " class=\"num\"" : "") + ">" + escape(cells[i]) +
           "</" + tag + ">";
  return out + "</tr>\n";
}

std::string readiness_section(const PipelineResult& r, const PipelineConfig& config) {
  std::vector<html::Badge> list;
  if (config.tetrahedralize.enabled) {
    const std::string tets = r.tet_quality ? std::to_string(r.tet_quality->tetrahedra) + " tets" : "none";
    list.push_back({"FEM-ready: tetrahedralised", tets, r.fem.ready});
  }
  for (html::Badge b : html::surface_badges(r.final_quality)) {
    if (b.name == "closed" && r.extrusion_depth)  // a terrain is closed by its block
      b = {"closed: extruded into a block", "base " + format_number(*r.extrusion_depth, 4) + " below", true};
    list.push_back(b);
  }
  if (r.tet_quality) {
    list.push_back({"no inverted tets", std::to_string(r.tet_quality->inverted_tets), r.tet_quality->inverted_tets == 0});
    const double smallest = r.tet_quality->min_dihedral_deg.min;
    list.push_back({"smallest dihedral \u2265 " + format_number(kDihedralWarningDeg, 2) + "\u00b0",
                    format_number(smallest, 3) + "\u00b0", smallest >= kDihedralWarningDeg});
  }
  std::string out = "<h2>FEM readiness</h2>\n" + html::badges(list);
  if (!r.fem.problems.empty()) {
    out += "<p>Why the surface is not FEM-ready:</p>\n<ul>\n";
    for (const std::string& p : r.fem.problems) out += "<li>" + escape(p) + "</li>\n";
    out += "</ul>\n";
  } else if (!config.tetrahedralize.enabled) {
    out += "<p class=\"note\">Tetrahedralisation was switched off.</p>\n";
  }
  return out + "<p class=\"note\">The surface checks are TetGen's needs; the shape targets (min angle, radius "
               "ratio) and the dihedral angle are FEM-grade goals.</p>\n";
}

std::string stage_table(const PipelineResult& r) {
  std::string out = "<h2>Stages</h2>\n<table>\n";
  out += row({"stage", "faces", "Hausdorff to input", "volume change", "radius ratio mean", "radius ratio p95",
              "min angle < 20\u00b0", "time (s)", "note"},
             "th");
  for (const StageRecord& s : r.stages) {
    const std::string faces = s.ran && s.faces_before != s.faces_after
                                  ? std::to_string(s.faces_before) + " \u2192 " + std::to_string(s.faces_after)
                                  : std::to_string(s.faces_after);
    if (!s.ran) {
      out += row({s.name, faces, "-", "-", "-", "-", "-", "-", "skipped: " + s.note});
      continue;
    }
    const std::string volume = s.volume_change_percent ? format_number(*s.volume_change_percent, 3) + " %" : "-";
    out += row({s.name, faces, optional_scientific(s.hausdorff_relative), volume, figure(s.radius_ratio_mean),
                figure(s.radius_ratio_p95), percent(s.faces_min_angle_below_20), format_fixed(s.seconds, 2), s.note});
  }
  return out + "</table>\n<p class=\"note\">Hausdorff distances are relative to the input surface's bounding-box "
               "diagonal" + std::string(r.from_points ? " (the input surface is the reconstruction)" : "") +
         "; every stage is measured against the input, not against the stage before.</p>\n";
}

std::string shape_histograms(const PipelineResult& r) {
  return "<h2>Triangle quality: input and output</h2>\n<div class=\"histograms\">\n" +
         html::radius_ratio_histogram(r.input_quality, "Radius ratio, input") +
         html::radius_ratio_histogram(r.final_quality, "Radius ratio, output") +
         html::min_angle_histogram(r.input_quality, "Minimum angle, input") +
         html::min_angle_histogram(r.final_quality, "Minimum angle, output") + "</div>\n";
}

std::string tet_section(const PipelineResult& r, const PipelineConfig& config) {
  if (!r.tet_quality) return {};
  const TetQualityReport& q = *r.tet_quality;
  std::string out = "<h2>Tetrahedra</h2>\n<div class=\"tables\">\n<table>\n";
  out += row({"tets", std::to_string(q.tetrahedra)});
  out += row({"points", std::to_string(q.points)});
  out += row({"volume", figure(q.volume)});
  out += row({"smallest dihedral", format_number(q.min_dihedral_deg.min, 4) + "\u00b0"});
  out += row({"dihedral p5", format_number(q.min_dihedral_deg.p5, 4) + "\u00b0"});
  out += row({"largest dihedral", format_number(q.max_dihedral_deg.max, 4) + "\u00b0"});
  out += row({"tets with a dihedral < 10\u00b0", percent(q.tets_min_dihedral_below_10)});
  out += row({"radius-edge ratio p95 / max", figure(q.radius_edge_ratio.p95) + " / " + figure(q.radius_edge_ratio.max)});
  out += row({"TetGen switches", r.tetgen_switches});
  out += row({"file", "tets." + config.tetrahedralize.format});
  out += "</table>\n</div>\n<div class=\"histograms\">\n";
  html::HistogramOptions dihedral;
  dihedral.title = "Smallest dihedral angle per tet";
  dihedral.x_label = "degrees";
  dihedral.unit = "tets";
  dihedral.lo = 0;
  dihedral.hi = 90;
  dihedral.bins = 45;
  dihedral.markers = html::percentile_markers(q.min_dihedral_deg);
  html::HistogramOptions radius_edge;
  radius_edge.title = "Radius-edge ratio per tet";
  radius_edge.x_label = "circumradius / shortest edge   (0.612 = regular)";
  radius_edge.unit = "tets";
  radius_edge.lo = 0.5;
  radius_edge.hi = 3;
  radius_edge.overflow = true;
  radius_edge.markers = html::percentile_markers(q.radius_edge_ratio);
  return out + html::svg_histogram(q.min_dihedral_per_tet, dihedral) +
         html::svg_histogram(q.radius_edge_per_tet, radius_edge) + "</div>\n";
}

std::string config_section(const PipelineConfig& config) {
  return "<h2>Configuration</h2>\n<details><summary>The effective configuration (pipeline.json replays the run "
         "with <code>--config</code>)</summary>\n<pre>" +
         escape(to_json(config).dump(2)) + "</pre>\n</details>\n";
}

}  // namespace

std::string pipeline_report_html(const PipelineResult& r, const PipelineConfig& config) {
  const std::string title = "meshprep pipeline: " + r.input;
  std::ostringstream intro;
  intro << (r.from_points ? std::to_string(r.input_points) + " points reconstructed into " : std::string())
        << r.input_quality.faces << " faces in, " << r.final_quality.faces << " faces out";
  if (r.tet_quality) intro << ", " << r.tet_quality->tetrahedra << " tets";
  intro << "; " << format_fixed(r.seconds, 1) << " s in all.";
  return html::page_start(title) + "<h1>meshprep pipeline: <span class=\"file\">" + escape(r.input) + "</span></h1>\n" +
         "<p>" + escape(intro.str()) + "</p>\n" + readiness_section(r, config) + "<h2>The final surface</h2>\n" +
         surface_picture_html(r.surface, r.final_quality) + stage_table(r) + shape_histograms(r) +
         tet_section(r, config) + config_section(config) +
         html::page_end("meshprep " MESHPREP_VERSION " pipeline report.");
}

}  // namespace meshprep
