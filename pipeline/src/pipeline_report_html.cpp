// report.html: one self-contained page for a whole run (inline CSS, SVG and PNG; no script).

#include "meshprep/pipeline/pipeline_outputs.h"

#include "meshprep/report/html_report.h"
#include "meshprep/report/number_format.h"
#include "meshprep/report/surface_picture.h"
#include "meshprep/core/patch_names.h"
#include "meshprep/quality/patch_table.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace meshprep {
namespace {

using html::escape;

std::string optional_scientific(const std::optional<double>& v) { return v ? format_scientific(*v, 2) : "-"; }

std::string percent(double fraction) { return std::isfinite(fraction) ? format_fixed(100 * fraction, 2) + " %" : "-"; }

std::string figure(double v) { return std::isfinite(v) ? format_number(v, 4) : "-"; }

std::string degrees(double v) { return std::isfinite(v) ? format_number(v, 4) + "\u00b0" : "-"; }

// A row of words: every cell aligned left.
std::string text_row(const std::vector<std::string>& cells, const char* tag = "td") {
  std::string out = "<tr>";
  for (const std::string& cell : cells) out += std::string("<") + tag + ">" + escape(cell) + "</" + tag + ">";
  return out + "</tr>\n";
}

std::string row(const std::vector<std::string>& cells, const char* tag = "td") {
  std::string out = "<tr>";
  for (std::size_t i = 0; i < cells.size(); ++i)
    out += std::string("<") + tag + (i > 0 && i + 1 < cells.size() ? " class=\"num\"" : "") + ">" + escape(cells[i]) +
           "</" + tag + ">";
  return out + "</tr>\n";
}

// The verdict in one line under the title: green when FEM-ready, red with every reason when not.
std::string headline(const PipelineResult& r, const PipelineConfig& config) {
  if (!config.tetrahedralize.enabled) return {};
  if (r.fem.ready)
    return "<p class=\"verdict pass\">\u2714 FEM-ready: " + std::to_string(r.tet_quality->tetrahedra) +
           " tets meet every threshold of the verdict.</p>\n";
  std::string why;
  for (const std::string& p : r.fem.problems) why += (why.empty() ? "" : "; ") + p;
  return "<p class=\"verdict fail\">\u2718 not FEM-ready: " + escape(why) + "</p>\n";
}

std::string readiness_section(const PipelineResult& r, const PipelineConfig& config) {
  std::vector<html::Badge> list;
  if (config.tetrahedralize.enabled) {
    const std::string tets = r.tet_quality ? std::to_string(r.tet_quality->tetrahedra) + " tets" : "none";
    list.push_back({"tetrahedralised", tets, r.tets.has_value()});
  }
  for (const ThresholdCheck& c : r.fem.checks) list.push_back({requirement(c), figure(c.value), c.ok});
  for (html::Badge b : html::surface_badges(r.final_quality)) {
    if (b.name == "closed" && r.extrusion_depth)  // a terrain is closed by its block
      b = {"closed: extruded into a block", "base " + format_number(*r.extrusion_depth, 4) + " below", true};
    list.push_back(b);
  }
  std::string out = "<h2>FEM readiness</h2>\n" + html::badges(list);
  if (!r.fem.problems.empty()) {
    out += "<p>Why it is not FEM-ready:</p>\n<ul>\n";
    for (const std::string& p : r.fem.problems) out += "<li>" + escape(p) + "</li>\n";
    out += "</ul>\n";
    if (r.tets)
      out += "<p>The tets are written (tets." + escape(config.tetrahedralize.format) +
             ") but do not meet the thresholds above; the worst are listed under Tetrahedra.</p>\n";
  } else if (!config.tetrahedralize.enabled) {
    out += "<p class=\"note\">Tetrahedralisation was switched off.</p>\n";
  }
  return out + "<p class=\"note\">FEM-ready means: tets were made and meet every threshold of the verdict (the "
               "configuration's <code>verdict</code> section). The surface checks are TetGen's needs; the triangle "
               "shape targets (min angle, radius ratio) are FEM-grade goals.</p>\n";
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

// Every piece of work a stage's guard took back (report.json: guards_taken_back), under the stages.
std::string taken_back_section(const PipelineResult& r) {
  std::string rows;
  for (const StageRecord& s : r.stages)
    for (const TakenBack& t : s.taken_back) {
      std::string figures;
      for (const FigureChange& f : figure_changes(t))
        figures += (figures.empty() ? "" : "; ") + f.name + " " + format_number(f.before, 4) + " \u2192 " +
                   format_number(f.after, 4);
      rows += text_row({t.stage, std::to_string(t.count) + " " + t.work, t.guard, t.reason, figures});
    }
  if (rows.empty()) return "<p class=\"note\">No guard took any stage's work back.</p>\n";
  return "<h3>Work the guards took back</h3>\n<table>\n" +
         text_row({"stage", "work", "guard", "why, and what was kept", "figures (as the work left them \u2192 as kept)"}, "th") +
         rows + "</table>\n";
}

std::string shape_histograms(const PipelineResult& r) {
  return "<h2>Triangle quality: input and output</h2>\n<div class=\"histograms\">\n" +
         html::radius_ratio_histogram(r.input_quality, "Radius ratio, input") +
         html::radius_ratio_histogram(r.final_quality, "Radius ratio, output") +
         html::min_angle_histogram(r.input_quality, "Minimum angle, input") +
         html::min_angle_histogram(r.final_quality, "Minimum angle, output") + "</div>\n";
}

// Each threshold of the verdict beside the tets' figure.
std::string threshold_table(const PipelineResult& r) {
  std::string out = "<table>\n<caption>Verdict</caption>\n" + row({"threshold", "figure", "holds"}, "th");
  for (const ThresholdCheck& c : r.fem.checks)
    out += "<tr><td>" + escape(requirement(c)) + "</td><td class=\"num\">" + figure(c.value) + "</td><td class=\"" +
           (c.ok ? "ok\">yes" : "problem\">no") + "</td></tr>\n";
  return out + "</table>\n";
}

// The tets of smallest dihedral angle, with their centroids: where to look in a viewer.
std::string worst_tets_table(const TetQualityReport& q) {
  if (q.worst_tets.empty()) return {};
  std::string out = "<table>\n<caption>The worst tets (smallest dihedral angle first)</caption>\n" +
                    row({"tet", "region", "centre x", "centre y", "centre z", "min dihedral", "max dihedral",
                         "radius-edge", "scaled Jacobian"},
                        "th");
  for (const WorstTet& w : q.worst_tets) {
    out += "<tr><td>" + std::to_string(w.index) + "</td>";
    for (const std::string& cell :
         {std::to_string(w.region), format_number(w.centre.x(), 6), format_number(w.centre.y(), 6),
          format_number(w.centre.z(), 6), degrees(w.shape.min_dihedral_deg), degrees(w.shape.max_dihedral_deg),
          figure(w.shape.radius_edge_ratio), figure(w.shape.scaled_jacobian)})
      out += "<td class=\"num\">" + escape(cell) + "</td>";
    out += "</tr>\n";
  }
  return out + "</table>\n";
}

// What the improvement did to TetGen's tets, and the boundary edges where the surface itself caps
// the smallest dihedral angle (improve_tets.h), with their places.
std::string improvement_tables(const PipelineResult& r) {
  if (!r.improvement) return {};
  const ImproveResult& i = *r.improvement;
  std::string out = "<table>\n<caption>Improvement of TetGen's tets</caption>\n" + row({"", "TetGen", "improved"}, "th");
  out += row({"smallest dihedral", degrees(i.min_dihedral_before_deg), degrees(i.min_dihedral_after_deg)});
  out += row({"largest dihedral", degrees(i.max_dihedral_before_deg), degrees(i.max_dihedral_after_deg)});
  out += row({"tets below the goal", std::to_string(i.below_goal_before), std::to_string(i.below_goal_after)});
  out += row({"tets", std::to_string(i.tets_before), std::to_string(i.tets_after)});
  out += "</table>\n<table>\n";
  out += row({"edge / multi-face removals", std::to_string(i.edge_removals) + " / " + std::to_string(i.multi_face_removals)});
  out += row({"vertex moves / contractions", std::to_string(i.vertex_moves) + " / " + std::to_string(i.contractions)});
  out += row({"new inner vertices", std::to_string(i.inserted_vertices)});
  out += row({"passes, stopped by", std::to_string(i.passes) + ", " + i.stopped_by});
  out += row({"time", format_fixed(i.seconds, 2) + " s"});
  out += "</table>\n";
  if (i.limiting_edges.empty()) return out;
  out += "<table>\n<caption>Where the surface forbids the goal: " + std::to_string(i.limiting_edge_count) +
         " boundary edge(s); no tets with this boundary do better than the bound</caption>\n" +
         row({"midpoint x", "midpoint y", "midpoint z", "interior angle", "bound"}, "th");
  for (std::size_t k = 0; k < i.limiting_edges.size() && k < 10; ++k) {
    const LimitingBoundaryEdge& e = i.limiting_edges[k];
    out += "<tr>";
    for (const std::string& cell : {format_number(e.midpoint.x(), 6), format_number(e.midpoint.y(), 6),
                                    format_number(e.midpoint.z(), 6), degrees(e.interior_angle_deg), degrees(e.bound_deg)})
      out += "<td class=\"num\">" + escape(cell) + "</td>";
    out += "</tr>\n";
  }
  return out + "</table>\n";
}

// Where the knife_edges stage changed the surface so that the tets can reach the goal, and what it
// left (knife_edges.h): each place with its figures, the displacement as a share of the diagonal.
std::string knife_edge_table(const PipelineResult& r) {
  if (!r.knife_edges || (r.knife_edges->edits.empty() && r.knife_edges->left.empty())) return {};
  const KnifeEdgeResult& k = *r.knife_edges;
  const double diagonal = r.input_quality.bbox_diagonal;
  std::string out = "<table>\n<caption>Knife edges and caps: " + std::to_string(k.edits.size()) +
                    " opened before the tets were made, " + std::to_string(k.left.size()) +
                    " left (no edit within the fidelity bound opened them)</caption>\n" +
                    row({"", "kind", "x", "y", "z", "angle", "bound before", "bound after", "moved / diagonal"}, "th");
  const auto add = [&](const KnifeEdgePlace& p, bool edit) {
    out += "<tr><td>" + escape(edit ? p.edit : "left") + "</td>";
    for (const std::string& cell :
         {std::string(p.kind), format_number(p.place.x(), 6), format_number(p.place.y(), 6), format_number(p.place.z(), 6),
          degrees(p.interior_angle_before_deg), degrees(p.bound_before_deg),
          edit ? degrees(p.bound_after_deg) : std::string(), edit ? figure(p.displacement / diagonal) : std::string()})
      out += "<td class=\"num\">" + escape(cell) + "</td>";
    out += "</tr>\n";
  };
  for (std::size_t i = 0; i < k.edits.size() && i < 20; ++i) add(k.edits[i], true);
  for (std::size_t i = 0; i < k.left.size() && i < 10; ++i) add(k.left[i], false);
  return out + "</table>\n";
}

// Per-tet histograms share a log count axis: the few tets that decide the verdict show beside
// the bulk.
html::HistogramOptions tet_histogram(const std::string& title, const std::string& x_label, double lo, double hi) {
  html::HistogramOptions o;
  o.title = title;
  o.x_label = x_label;
  o.unit = "tets";
  o.lo = lo;
  o.hi = hi;
  o.log_counts = true;
  return o;
}

std::string tet_section(const PipelineResult& r, const PipelineConfig& config) {
  if (!r.tet_quality) return {};
  const TetQualityReport& q = *r.tet_quality;
  std::string out = "<h2>Tetrahedra</h2>\n<div class=\"tables\">\n<table>\n";
  out += row({"tets", std::to_string(q.tetrahedra)});
  out += row({"points", std::to_string(q.points)});
  out += row({"volume", figure(q.volume)});
  out += row({"smallest dihedral", degrees(q.min_dihedral_deg.min)});
  out += row({"dihedral p5", degrees(q.min_dihedral_deg.p5)});
  out += row({"largest dihedral", degrees(q.max_dihedral_deg.max)});
  out += row({"tets with a dihedral < 10\u00b0", percent(q.tets_min_dihedral_below_10)});
  out += row({"radius-edge ratio p95 / max", figure(q.radius_edge_ratio.p95) + " / " + figure(q.radius_edge_ratio.max)});
  out += row({"scaled Jacobian min / p5", figure(q.scaled_jacobian.min) + " / " + figure(q.scaled_jacobian.p5)});
  out += row({"aspect ratio p95 / max", figure(q.aspect_ratio.p95) + " / " + figure(q.aspect_ratio.max)});
  out += row({"TetGen switches", r.tetgen_switches});
  out += row({"file", "tets." + config.tetrahedralize.format});
  out += "</table>\n" + threshold_table(r) + "</div>\n<div class=\"tables\">\n" + improvement_tables(r) + knife_edge_table(r) +
         "</div>\n<div class=\"tables\">\n" + worst_tets_table(q) + "</div>\n<div class=\"histograms\">\n";
  html::HistogramOptions dihedral = tet_histogram("Smallest dihedral angle per tet", "degrees", 0, 90);
  dihedral.bins = 45;
  dihedral.markers = html::percentile_markers(q.min_dihedral_deg);
  dihedral.markers.push_back({"threshold", config.verdict.min_dihedral_deg});
  html::HistogramOptions radius_edge =
      tet_histogram("Radius-edge ratio per tet", "circumradius / shortest edge   (0.612 = regular)", 0.5, 3);
  radius_edge.overflow = true;
  radius_edge.markers = html::percentile_markers(q.radius_edge_ratio);
  html::HistogramOptions jacobian =
      tet_histogram("Scaled Jacobian per tet (Verdict)", "1 = regular, 0 = flat, < 0 = inverted", -1, 1);
  jacobian.markers = html::percentile_markers(q.scaled_jacobian);
  return out + html::svg_histogram(q.min_dihedral_per_tet, dihedral) +
         html::svg_histogram(q.radius_edge_per_tet, radius_edge) +
         html::svg_histogram(q.scaled_jacobian_per_tet, jacobian) + "</div>\n";
}

// The boundary patches: a row each (the input's area, the final one's and its change, the tets'
// faces), and the final surface coloured by patch.
std::string patch_section(const PipelineResult& r) {
  const std::vector<PatchRow> input = patch_table(r.input_surface), final_rows = patch_table(r.surface);
  if (final_rows.empty()) return {};
  std::map<int, double> input_area;
  for (const PatchRow& row : input) input_area[row.tag] = row.area;
  std::map<int, std::size_t> tet_faces;
  if (r.tets)
    for (const int tag : r.tets->boundary_tags) ++tet_faces[tag];
  std::string out = "<h2>Boundary patches</h2>\n<p>" + std::to_string(final_rows.size()) +
                    " patches: the named sets of faces where a solver fixes, loads or heats the part. Every stage "
                    "keeps each face's patch; the tets carry them as boundary tags with these names.</p>\n"
                    "<div class=\"tables\">\n<table>\n" +
                    row({"patch", "faces", "area", "change from the input", "normal spread", "tet faces"}, "th");
  for (const PatchRow& patch : final_rows) {
    const auto before = input_area.find(patch.tag);
    const std::string change = before != input_area.end() && before->second > 0
                                   ? format_fixed(100 * (patch.area / before->second - 1), 3) + " %"
                                   : "-";
    const auto faces = tet_faces.find(patch.tag);
    out += row({patch.name, std::to_string(patch.faces), figure(patch.area), change, degrees(patch.normal_spread_deg),
                faces != tet_faces.end() ? std::to_string(faces->second) : "-"});
  }
  if (r.tets)  // a block's sides and bottom
    for (const auto& [tag, count] : tet_faces) {
      const int block_tag = tag;  // (a lambda may not capture a structured binding in C++17)
      if (std::none_of(final_rows.begin(), final_rows.end(), [&](const PatchRow& patch) { return patch.tag == block_tag; }))
        out += row({tag_name(r.tets->boundary_names, tag, "boundary"), "-", "-", "-", "-", std::to_string(count)});
    }
  return out + "</table>\n</div>\n" + patch_picture_html(r.surface);
}

// The size field the surface and the tets followed, and how they follow it: the figures, the
// histogram of the tet edges' length / h, and the boundary coloured by it.
std::string size_section(const PipelineResult& r) {
  if (!r.size_field || !r.size_conformity || !r.tets) return {};
  const SizeField& field = *r.size_field;
  const SizeConformity& c = *r.size_conformity;
  std::string out = "<h2>Element size</h2>\n<p>The size field h(x) the surface's remeshing and the tets followed "
                    "(docs/size_field.md), and each tet edge's length over h at its midpoint.</p>\n"
                    "<div class=\"tables\">\n<table>\n<caption>Size field</caption>\n";
  out += row({"longest h (the size where nothing asks for less)", figure(field.longest())});
  out += row({"shortest h asked", figure(field.shortest())});
  out += row({"grading", figure(field.grading())});
  out += row({"point demands (curvature, thickness, patches)", std::to_string(field.demands())});
  out += row({"regions", std::to_string(field.regions())});
  out += "</table>\n<table>\n<caption>Tet edges against it</caption>\n";
  out += row({"edges", std::to_string(c.edges)});
  out += row({"length / h within [" + figure(kSizeBandLow) + ", " + figure(kSizeBandHigh) + "]", percent(c.within_band)});
  out += row({"length / h p5 / median / p95", figure(c.ratio_p05) + " / " + figure(c.ratio_median) + " / " + figure(c.ratio_p95)});
  out += row({"grading excess p99 / max", figure(c.grading_excess_p99) + " / " + figure(c.grading_excess_max)});
  out += "</table>\n</div>\n<div class=\"histograms\">\n";
  html::HistogramOptions ratio;
  ratio.title = "Tet edge length / h";
  ratio.x_label = "length over the size asked at the edge's midpoint   (1 = as asked)";
  ratio.unit = "edges";
  ratio.lo = 0;
  ratio.hi = 3;
  ratio.bins = 60;
  ratio.overflow = true;
  ratio.markers = {{"band " + figure(kSizeBandLow), kSizeBandLow}, {"median " + figure(c.ratio_median), c.ratio_median},
                   {"band " + figure(kSizeBandHigh), kSizeBandHigh}};
  out += html::svg_histogram(c.edge_ratios, ratio) + "</div>\n";
  // The boundary as the tets have it, each face by its mean edge over h at its centroid.
  TriangleSoup boundary;
  boundary.points = r.tets->points;
  boundary.triangles = r.tets->boundary_faces;
  std::vector<double> ratios;
  ratios.reserve(boundary.triangles.size());
  for (const Triangle& t : boundary.triangles) {
    const Vec3 &a = boundary.points[t[0]], &b = boundary.points[t[1]], &c3 = boundary.points[t[2]];
    ratios.push_back(((b - a).norm() + (c3 - b).norm() + (a - c3).norm()) / 3 / field((a + b + c3) / 3.0));
  }
  return out + size_ratio_picture_html(boundary, ratios);
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
         headline(r, config) + "<p>" + escape(intro.str()) + "</p>\n" + readiness_section(r, config) + "<h2>The final surface</h2>\n" +
         surface_picture_html(r.surface, r.final_quality) + stage_table(r) + taken_back_section(r) + shape_histograms(r) +
         patch_section(r) + tet_section(r, config) + size_section(r) + config_section(config) +
         html::page_end("meshprep " MESHPREP_VERSION " pipeline report.");
}

}  // namespace meshprep
