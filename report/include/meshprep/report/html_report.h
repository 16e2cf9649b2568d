#pragma once
/// \file html_report.h
/// The pieces of meshprep's self-contained HTML reports (inline CSS, SVG and PNG; no script, no
/// external resource), shared by `meshprep quality --html` and the pipeline's report.html.

#include "meshprep/core/mesh.h"
#include "meshprep/quality/report.h"

#include <string>
#include <vector>

namespace meshprep::html {

/// `text` with &, <, >, " and ' replaced by character references (for HTML/XML text and attributes).
std::string escape(const std::string& text);

/// The page's head (with the shared style sheet and `title`) up to and including <body>.
std::string page_start(const std::string& title);

/// </body></html>, after a footer holding `footer` (escaped).
std::string page_end(const std::string& footer);

/// A green or red check with its measured value.
struct Badge {
  std::string name;
  std::string value;
  bool pass = false;
};

/// A row of badges (<ul class="badges">).
std::string badges(const std::vector<Badge>& list);

/// The checks of a surface: closed, manifold, oriented, no degenerate, duplicate or
/// self-intersecting faces, and the FEM-grade shape targets (min angle < 20 deg on <= 5 % of the
/// faces, radius ratio p95 <= 2).
std::vector<Badge> surface_badges(const QualityReport& report);

/// A vertical dashed line at a value, labelled e.g. "p50 1.12".
struct HistogramMarker {
  std::string label;
  double value = 0;
};

struct HistogramOptions {
  std::string title;                     ///< drawn above the plot
  std::string x_label;                   ///< drawn under the x axis
  std::string unit = "faces";            ///< what is counted, for the y axis and the tooltips
  double lo = 0, hi = 1;                 ///< the binned range (lo < hi, both finite)
  std::size_t bins = 40;                 ///< equal-width bins over [lo, hi]
  bool overflow = false;                 ///< values above hi (+inf included) get their own bar ">hi"
  std::vector<HistogramMarker> markers;  ///< e.g. the percentiles
  int width = 560, height = 270;         ///< in pixels
  /// Counts on a logarithmic axis (ticks 1, 10, 100, ...; the axis label says "log scale"), so that
  /// a tail of a few elements beside bins of thousands shows: the axis starts at 1/2, a bin of one
  /// is a bar a third of a decade high, an empty bin none.
  bool log_counts = false;
};

/// An <svg> element with a bar per bin (its range and count in a <title> tooltip), axes with ticks
/// and labels, and the markers. Values below lo are counted in the first bin, values above hi in
/// the last bin or, with `overflow`, in the overflow bar. NaN values are not plotted; their number
/// is given under the title.
/// \throws InvalidInput if the range is empty or not finite or there are no bins.
std::string svg_histogram(const std::vector<double>& values, const HistogramOptions& options);

/// Markers at the 5th, 50th and 95th percentiles of `d`.
std::vector<HistogramMarker> percentile_markers(const Distribution& d);

/// The histogram of the faces' radius ratio (1 to 5, beyond in an overflow bar) with its percentiles.
std::string radius_ratio_histogram(const QualityReport& report, const std::string& title);

/// The histogram of the faces' smallest angle (0 to 60 degrees) with its percentiles.
std::string min_angle_histogram(const QualityReport& report, const std::string& title);

}  // namespace meshprep::html
