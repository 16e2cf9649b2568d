#pragma once
/// \file svg_histogram.h
/// Inline SVG histograms for self-contained HTML reports (no script, no external resource).
/// Private to the module; shared by every report that plots a per-element measure.

#include <string>
#include <vector>

namespace meshprep::detail {

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
};

/// An <svg> element with a bar per bin (its range and count in a <title> tooltip), axes with ticks
/// and labels, and the markers. Values below lo are counted in the first bin, values above hi in
/// the last bin or, with `overflow`, in the overflow bar. NaN values are not plotted; their number
/// is given under the title.
/// \throws InvalidInput if the range is empty or not finite or there are no bins.
std::string svg_histogram(const std::vector<double>& values, const HistogramOptions& options);

/// `text` with &, <, >, " and ' replaced by character references (for HTML/XML text and attributes).
std::string xml_escape(const std::string& text);

}  // namespace meshprep::detail
