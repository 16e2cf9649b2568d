// svg_histogram's count axis: linear, or logarithmic so that a thin tail shows.
#include "meshprep/report/html_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace meshprep {
namespace {

// The height of the visible bar whose tooltip is `tooltip` (bar(): a <title>, a transparent
// full-height rect, then the bar's rect).
double bar_height(const std::string& svg, const std::string& tooltip) {
  std::size_t at = svg.find("<title>" + tooltip + "</title>");
  if (at == std::string::npos) return -1;
  for (int rect = 0; rect < 2; ++rect) at = svg.find("height=\"", at) + 8;
  return std::stod(svg.substr(at, svg.find('"', at) - at));
}

// 1000 values in [50, 52) and one in [4, 6): a tail of 0.1 %.
std::vector<double> bulk_and_tail() {
  std::vector<double> values(1000, 51.0);
  values.push_back(5.0);
  return values;
}

html::HistogramOptions options(bool log_counts) {
  html::HistogramOptions o;
  o.unit = "tets";
  o.lo = 0;
  o.hi = 90;
  o.bins = 45;
  o.log_counts = log_counts;
  return o;
}

TEST(SvgHistogram, LinearCountsHideAOneElementTail) {
  const std::string svg = html::svg_histogram(bulk_and_tail(), options(false));
  const double bulk = bar_height(svg, "50 \u2013 52: 1000 tets"), tail = bar_height(svg, "4 \u2013 6: 1 tets");
  ASSERT_GT(bulk, 100);
  EXPECT_LT(tail, 0.01 * bulk);  // 1/1000 of the bulk's bar, rounded to 0.1 px
  EXPECT_EQ(svg.find("log scale"), std::string::npos);
}

TEST(SvgHistogram, LogCountsShowAOneElementTailAndSaySo) {
  const std::string svg = html::svg_histogram(bulk_and_tail(), options(true));
  const double bulk = bar_height(svg, "50 \u2013 52: 1000 tets"), tail = bar_height(svg, "4 \u2013 6: 1 tets");
  ASSERT_GT(bulk, 100);
  // The axis runs from 1/2 to 1000 (the decade at the largest count): heights are log(count / 0.5)
  // over log(2000), so the single tet's bar is log 2 / log 2000 of the bulk's (0.1 px rounding).
  EXPECT_NEAR(tail / bulk, std::log(2.0) / std::log(2000.0), 0.2 / bulk + 1e-3);
  EXPECT_EQ(bar_height(svg, "6 \u2013 8: 0 tets"), 0.0);  // an empty bin has no bar
  EXPECT_NE(svg.find(">tets (log scale)</text>"), std::string::npos);
  for (const char* tick : {">1</text>", ">10</text>", ">100</text>", ">1000</text>"})
    EXPECT_NE(svg.find(tick), std::string::npos) << tick;
}

}  // namespace
}  // namespace meshprep
