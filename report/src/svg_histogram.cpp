// svg_histogram and escape: a bar chart as inline SVG, drawn with plain elements (no script, no external resource).

#include "meshprep/report/html_report.h"

#include "meshprep/core/errors.h"
#include "meshprep/report/number_format.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace meshprep::html {
namespace {

constexpr double kMarginLeft = 58, kMarginRight = 12, kMarginTop = 30, kMarginBottom = 44;
constexpr double kOverflowGap = 10, kOverflowWidth = 18;  // the overflow bar, right of the bins
constexpr double kMarkerRow = 12;                         // height of a marker label row
constexpr double kLogFloor = 0.5;  // where a log count axis starts: a bin of one stays visible

struct Bins {
  std::vector<std::size_t> counts;
  std::size_t overflow = 0;   ///< values above hi, when the options ask for an overflow bar
  std::size_t infinite = 0;   ///< of those, +inf
  std::size_t undefined = 0;  ///< NaN: not plotted
};

Bins count_bins(const std::vector<double>& values, const HistogramOptions& o) {
  Bins bins;
  bins.counts.assign(o.bins, 0);
  const double bin_width = (o.hi - o.lo) / static_cast<double>(o.bins);
  for (double v : values) {
    if (std::isnan(v)) {
      ++bins.undefined;
    } else if (o.overflow && v > o.hi) {
      ++bins.overflow;
      if (std::isinf(v)) ++bins.infinite;
    } else {
      const double i = std::clamp(std::floor((v - o.lo) / bin_width), 0.0, static_cast<double>(o.bins - 1));
      ++bins.counts[static_cast<std::size_t>(i)];
    }
  }
  return bins;
}

// 1, 2 or 5 times a power of ten, so that `range` holds about `ticks` steps.
double nice_step(double range, double ticks) {
  const double raw = range / ticks;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * magnitude >= raw) return m * magnitude;
  return 10 * magnitude;
}

std::vector<double> ticks_between(double lo, double hi, double step) {
  std::vector<double> ticks;
  const double first = std::ceil(lo / step - 1e-9);
  for (double i = first; i * step <= hi + 1e-9 * step; ++i) ticks.push_back(i * step + 0.0);  // + 0.0: no "-0"
  return ticks;
}

std::string px(double v) { return format_fixed(v, 1); }

/// Pixel geometry: the plot area, the bins' extent inside it, and the count scale.
struct Frame {
  double left, right, top, bottom;
  double bins_right;  ///< right end of the regular bins (the overflow bar is beyond)
  double bars_top;    ///< where the largest count (ymax) is drawn; marker labels go above
  double lo, hi, ymax;
  bool log_counts;    ///< counts on a log axis from kLogFloor to ymax

  double x(double v) const { return left + (v - lo) / (hi - lo) * (bins_right - left); }
  double y(double count) const {
    if (!log_counts) return bottom - count / ymax * (bottom - bars_top);
    if (count <= 0) return bottom;
    return bottom - std::log(count / kLogFloor) / std::log(ymax / kLogFloor) * (bottom - bars_top);
  }
  double overflow_left() const { return bins_right + kOverflowGap; }
};

// The top of the count axis: a round number above the largest count (linear), or the power of
// ten at or above it, 10 at least (log).
double count_axis_top(std::size_t largest, bool log_counts) {
  const double top = std::max<double>(1, static_cast<double>(largest));
  if (log_counts) return std::max(10.0, std::pow(10.0, std::ceil(std::log10(top))));
  const double step = std::max(1.0, nice_step(top, 4));
  return std::ceil(top / step) * step;
}

// The count axis' ticks: 1, 10, 100, ... up to ymax on a log axis, round steps from 0 otherwise.
std::vector<double> count_ticks(const Frame& f) {
  if (!f.log_counts) return ticks_between(0, f.ymax, nice_step(f.ymax, 4));
  std::vector<double> ticks;
  for (double t = 1; t <= f.ymax * (1 + 1e-9); t *= 10) ticks.push_back(t);
  return ticks;
}

Frame make_frame(const HistogramOptions& o, double ymax) {
  Frame f{};
  f.left = kMarginLeft;
  f.right = o.width - kMarginRight;
  f.top = kMarginTop;
  f.bottom = o.height - kMarginBottom;
  f.bins_right = o.overflow ? f.right - kOverflowGap - kOverflowWidth : f.right;
  f.bars_top = f.top + kMarkerRow * static_cast<double>(o.markers.size()) + 4;
  f.lo = o.lo;
  f.hi = o.hi;
  f.ymax = ymax;
  f.log_counts = o.log_counts;
  return f;
}

void bar(std::ostream& svg, double x0, double x1, double y, double bottom, const std::string& fill,
         const std::string& tooltip, double top) {
  // A transparent full-height rectangle makes the tooltip reachable even for empty bins.
  svg << "<g><title>" << escape(tooltip) << "</title>"
      << "<rect x=\"" << px(x0) << "\" y=\"" << px(top) << "\" width=\"" << px(x1 - x0) << "\" height=\""
      << px(bottom - top) << "\" fill=\"#000\" fill-opacity=\"0\"/>"
      << "<rect x=\"" << px(x0) << "\" y=\"" << px(y) << "\" width=\"" << px(x1 - x0) << "\" height=\""
      << px(bottom - y) << "\" fill=\"" << fill << "\" stroke=\"#fff\" stroke-width=\"0.5\"/></g>\n";
}

void draw_bins(std::ostream& svg, const Bins& bins, const Frame& f, const HistogramOptions& o) {
  const double step = (o.hi - o.lo) / static_cast<double>(o.bins);
  for (std::size_t i = 0; i < bins.counts.size(); ++i) {
    const double a = o.lo + step * static_cast<double>(i), b = a + step;
    const std::string tooltip = format_number(a, 4) + " \u2013 " + format_number(b, 4) + ": " +
                                std::to_string(bins.counts[i]) + " " + o.unit;
    bar(svg, f.x(a), f.x(b), f.y(static_cast<double>(bins.counts[i])), f.bottom, "#4a78b0", tooltip, f.top);
  }
}

void draw_overflow(std::ostream& svg, const Bins& bins, const Frame& f, const HistogramOptions& o) {
  const std::string label = ">" + format_number(o.hi, 4);
  std::string tooltip = label + ": " + std::to_string(bins.overflow) + " " + o.unit;
  if (bins.infinite > 0) tooltip += " (" + std::to_string(bins.infinite) + " infinite)";
  const double x0 = f.overflow_left();
  bar(svg, x0, x0 + kOverflowWidth, f.y(static_cast<double>(bins.overflow)), f.bottom, "#c0504d", tooltip, f.top);
  svg << "<text x=\"" << px(x0 + kOverflowWidth / 2) << "\" y=\"" << px(f.bottom + 14)
      << "\" text-anchor=\"middle\" fill=\"#c0504d\">" << escape(label) << "</text>\n";
}

void draw_axes(std::ostream& svg, const Frame& f, const HistogramOptions& o) {
  for (double t : count_ticks(f)) {
    svg << "<line x1=\"" << px(f.left) << "\" x2=\"" << px(f.right) << "\" y1=\"" << px(f.y(t)) << "\" y2=\""
        << px(f.y(t)) << "\" stroke=\"#e4e4e4\"/><text x=\"" << px(f.left - 4) << "\" y=\"" << px(f.y(t) + 4)
        << "\" text-anchor=\"end\">" << static_cast<long long>(t) << "</text>\n";
  }
  for (double t : ticks_between(o.lo, o.hi, nice_step(o.hi - o.lo, 6))) {
    svg << "<line x1=\"" << px(f.x(t)) << "\" x2=\"" << px(f.x(t)) << "\" y1=\"" << px(f.bottom) << "\" y2=\""
        << px(f.bottom + 4) << "\" stroke=\"#333\"/><text x=\"" << px(f.x(t)) << "\" y=\"" << px(f.bottom + 14)
        << "\" text-anchor=\"middle\">" << format_number(t, 4) << "</text>\n";
  }
  svg << "<line x1=\"" << px(f.left) << "\" x2=\"" << px(f.right) << "\" y1=\"" << px(f.bottom) << "\" y2=\""
      << px(f.bottom) << "\" stroke=\"#333\"/>\n"
      << "<text x=\"" << px((f.left + f.right) / 2) << "\" y=\"" << px(o.height - 6.0)
      << "\" text-anchor=\"middle\">" << escape(o.x_label) << "</text>\n"
      << "<text transform=\"translate(14," << px((f.top + f.bottom) / 2)
      << ") rotate(-90)\" text-anchor=\"middle\">" << escape(o.log_counts ? o.unit + " (log scale)" : o.unit)
      << "</text>\n";
}

// Where a marker is drawn: at its value, at the overflow bar beyond hi, at an edge otherwise.
double marker_x(double v, const Frame& f, const HistogramOptions& o) {
  if (v > o.hi && o.overflow) return f.overflow_left() + kOverflowWidth / 2;
  return f.x(std::clamp(v, o.lo, o.hi));
}

void draw_markers(std::ostream& svg, const Frame& f, const HistogramOptions& o) {
  double row_y = f.top + kMarkerRow - 2;
  for (const HistogramMarker& m : o.markers) {
    if (!std::isnan(m.value)) {
      const double x = marker_x(m.value, f, o);
      const bool left_of_line = x > (f.left + f.right) / 2;  // keep the label inside the plot
      svg << "<line x1=\"" << px(x) << "\" x2=\"" << px(x) << "\" y1=\"" << px(row_y + 2) << "\" y2=\""
          << px(f.bottom) << "\" stroke=\"#d9822b\" stroke-width=\"1.5\" stroke-dasharray=\"4 3\"/>"
          << "<text x=\"" << px(left_of_line ? x - 3 : x + 3) << "\" y=\"" << px(row_y) << "\" text-anchor=\""
          << (left_of_line ? "end" : "start") << "\" fill=\"#a85a12\">" << escape(m.label) << ' '
          << format_number(m.value, 4) << "</text>\n";
    }
    row_y += kMarkerRow;
  }
}

void draw_title(std::ostream& svg, const Bins& bins, const HistogramOptions& o) {
  svg << "<text x=\"8\" y=\"16\" font-size=\"13\" font-weight=\"bold\">" << escape(o.title);
  if (bins.undefined > 0)
    svg << "<tspan font-size=\"11\" font-weight=\"normal\" fill=\"#666\"> (" << bins.undefined << " undefined, not shown)</tspan>";
  svg << "</text>\n";
}

void require_valid(const HistogramOptions& o) {
  if (!(std::isfinite(o.lo) && std::isfinite(o.hi) && o.lo < o.hi) || o.bins == 0)
    throw InvalidInput("svg_histogram: needs a finite range lo < hi and at least one bin");
}

}  // namespace

std::string svg_histogram(const std::vector<double>& values, const HistogramOptions& options) {
  require_valid(options);
  const Bins bins = count_bins(values, options);
  const std::size_t largest = std::max(*std::max_element(bins.counts.begin(), bins.counts.end()), bins.overflow);
  const Frame frame = make_frame(options, count_axis_top(largest, options.log_counts));

  std::ostringstream svg;
  svg << "<svg class=\"histogram\" width=\"" << options.width << "\" height=\"" << options.height << "\" viewBox=\"0 0 "
      << options.width << ' ' << options.height << "\" role=\"img\" aria-label=\"" << escape(options.title)
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  draw_title(svg, bins, options);
  draw_axes(svg, frame, options);
  draw_bins(svg, bins, frame, options);
  if (options.overflow) draw_overflow(svg, bins, frame, options);
  draw_markers(svg, frame, options);
  svg << "</svg>\n";
  return svg.str();
}

std::string escape(const std::string& text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': escaped += "&amp;"; break;
      case '<': escaped += "&lt;"; break;
      case '>': escaped += "&gt;"; break;
      case '"': escaped += "&quot;"; break;
      case '\'': escaped += "&#39;"; break;
      default: escaped += c;
    }
  }
  return escaped;
}

}  // namespace meshprep::html
