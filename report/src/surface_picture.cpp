// The report's pictures of a surface: the views from its principal axes, the PNG images as data
// URIs, the caption and the colour legend.

#include "meshprep/report/surface_picture.h"

#include "meshprep/report/html_report.h"
#include "meshprep/report/number_format.h"

#include "base64.h"

#include <Eigen/Eigenvalues>

#include "meshprep/core/patch_names.h"

#include <cmath>
#include <map>

namespace meshprep {
namespace {

constexpr double kTiltDeg = 30;          // the camera's tilt about the longest axis
constexpr double kGoodRatio = 1, kBadRatio = 3;  // the colour scale of the radius ratio
constexpr int kPictureWidth = 560, kPictureHeight = 420;

// A horizontal bar of the colour scale with ticks, as inline SVG.
std::string legend() {
  constexpr int width = 300, steps = 60;
  std::string svg = "<svg width=\"" + std::to_string(width + 40) +
                    "\" height=\"46\" role=\"img\" aria-label=\"colour scale of the radius ratio\">\n";
  for (int i = 0; i < steps; ++i) {
    const double value = kGoodRatio + (kBadRatio - kGoodRatio) * (i + 0.5) / steps;
    const auto c = quality_colour(value, kGoodRatio, kBadRatio);
    svg += "<rect x=\"" + std::to_string(20 + i * width / steps) + "\" y=\"4\" width=\"" +
           std::to_string(width / steps + 1) + "\" height=\"16\" fill=\"rgb(" + std::to_string(c[0]) + "," +
           std::to_string(c[1]) + "," + std::to_string(c[2]) + ")\"/>\n";
  }
  for (double tick = kGoodRatio; tick <= kBadRatio + 1e-9; tick += 0.5) {
    const double x = 20 + width * (tick - kGoodRatio) / (kBadRatio - kGoodRatio);
    svg += "<text x=\"" + format_fixed(x, 1) + "\" y=\"36\" font-size=\"12\" text-anchor=\"middle\">" +
           format_number(tick, 2) + (tick >= kBadRatio ? "+" : "") + "</text>\n";
  }
  return svg + "</svg>\n";
}

// The size ratio's colour scale: log2 of length / h from -1 (half the size asked) to 1 (twice).
constexpr double kRatioScaleLow = -1, kRatioScaleHigh = 1;

std::array<std::uint8_t, 3> ratio_colour(double ratio) {
  return diverging_colour(ratio > 0 ? std::log2(ratio) : -INFINITY, kRatioScaleLow, kRatioScaleHigh);
}

std::string ratio_legend() {
  constexpr int width = 300, steps = 60;
  std::string svg = "<svg width=\"" + std::to_string(width + 40) +
                    "\" height=\"46\" role=\"img\" aria-label=\"colour scale of edge length over the size asked\">\n";
  for (int i = 0; i < steps; ++i) {
    const auto c = ratio_colour(std::exp2(kRatioScaleLow + (kRatioScaleHigh - kRatioScaleLow) * (i + 0.5) / steps));
    svg += "<rect x=\"" + std::to_string(20 + i * width / steps) + "\" y=\"4\" width=\"" +
           std::to_string(width / steps + 1) + "\" height=\"16\" fill=\"rgb(" + std::to_string(c[0]) + "," +
           std::to_string(c[1]) + "," + std::to_string(c[2]) + ")\"/>\n";
  }
  for (const double tick : {0.5, 0.7, 1.0, 1.4, 2.0}) {
    const double x = 20 + width * (std::log2(tick) - kRatioScaleLow) / (kRatioScaleHigh - kRatioScaleLow);
    svg += "<text x=\"" + format_fixed(x, 1) + "\" y=\"36\" font-size=\"12\" text-anchor=\"middle\">" +
           (tick == 0.5 ? "\u2264" : "") + format_number(tick, 2) + (tick == 2.0 ? "+" : "") + "</text>\n";
  }
  return svg + "</svg>\n";
}

}  // namespace

std::vector<SurfaceView> report_views(const TriangleSoup& soup, int width, int height) {
  Vec3 mean = Vec3::Zero(), normal_sum = Vec3::Zero();
  double normal_lengths = 0;
  for (const Vec3& p : soup.points) mean += p;
  mean /= static_cast<double>(std::max<std::size_t>(1, soup.points.size()));
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Vec3& p : soup.points) covariance += (p - mean) * (p - mean).transpose();
  for (const Triangle& t : soup.triangles) {
    const Vec3 n = (soup.points[t[1]] - soup.points[t[0]]).cross(soup.points[t[2]] - soup.points[t[0]]);
    normal_sum += n;
    normal_lengths += n.norm();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> pca(covariance);
  const Vec3 middle = pca.eigenvectors().col(1);  // drawn upwards; the longest axis lies across the image
  Vec3 shortest = pca.eigenvectors().col(0);
  // An open surface (a terrain) is seen from the side its faces look to; a closed one's normals
  // cancel out (to round-off), and it is seen from both sides.
  const bool open = normal_sum.norm() > 1e-6 * normal_lengths;
  if (open && normal_sum.dot(shortest) < 0) shortest = -shortest;
  const double tilt = kTiltDeg * M_PI / 180;
  std::vector<SurfaceView> views;
  for (const double side : {1.0, -1.0}) {
    if (open && side < 0) break;
    SurfaceView view;
    // From the shortest axis' side, tilted about the longest axis so that relief shows.
    view.direction = -side * std::cos(tilt) * shortest + std::sin(tilt) * middle;
    view.up = middle;
    view.width = width;
    view.height = height;
    views.push_back(view);
  }
  return views;
}

// The views of `soup`, face f in colours[f], as <figure>s; `what` completes the alt text.
std::string figures(const TriangleSoup& soup, const std::vector<std::array<std::uint8_t, 3>>& colours,
                    const std::string& what) {
  const std::vector<SurfaceView> views = report_views(soup, kPictureWidth, kPictureHeight);
  std::string out;
  for (std::size_t i = 0; i < views.size(); ++i) {
    const RgbImage image = render_surface(soup, colours, views[i]);
    out += "<figure><img width=\"" + std::to_string(image.width) + "\" height=\"" + std::to_string(image.height) +
           "\" alt=\"the surface, view " + std::to_string(i + 1) + ", " + what + "\" src=\"data:image/png;base64," +
           detail::base64(encode_png(image)) + "\"><figcaption>" + (views.size() > 1 ? (i == 0 ? "Front" : "Back") : "View") +
           " (principal axes, tilted " + format_number(kTiltDeg, 2) + "\u00b0)</figcaption></figure>\n";
  }
  return out;
}

std::string surface_picture_html(const TriangleSoup& soup, const QualityReport& report) {
  if (soup.triangles.empty() || report.face_shapes.size() != soup.triangles.size()) return {};
  std::vector<std::array<std::uint8_t, 3>> colours;
  colours.reserve(report.face_shapes.size());
  for (const TriangleShape& shape : report.face_shapes) colours.push_back(quality_colour(shape.radius_ratio, kGoodRatio, kBadRatio));
  return "<div class=\"pictures\">\n" + figures(soup, colours, "coloured by radius ratio") + "<figure>" + legend() +
         "<figcaption>Faces coloured by radius ratio R / (2 r): 1 is equilateral; 3 and above, red, is a sliver. "
         "Rendered by meshprep (z-buffer, hidden surfaces removed).</figcaption></figure>\n</div>\n";
}

std::string size_ratio_picture_html(const TriangleSoup& soup, const std::vector<double>& face_ratios) {
  if (soup.triangles.empty() || face_ratios.size() != soup.triangles.size()) return {};
  std::vector<std::array<std::uint8_t, 3>> colours;
  colours.reserve(face_ratios.size());
  for (const double ratio : face_ratios) colours.push_back(ratio_colour(ratio));
  return "<div class=\"pictures\">\n" + figures(soup, colours, "coloured by edge length over the size asked") +
         "<figure>" + ratio_legend() +
         "<figcaption>Boundary faces coloured by their mean edge length over the size field's h at their centroid: "
         "white as asked, blue finer, red coarser (log scale).</figcaption></figure>\n</div>\n";
}

std::string patch_picture_html(const TriangleSoup& soup) {
  if (soup.triangles.empty() || soup.patches.size() != soup.triangles.size()) return {};
  std::map<int, int> index;  // tag -> colour index, in tag order
  for (const int tag : soup.patches) index.emplace(tag, 0);
  int next = 0;
  for (auto& [tag, i] : index) i = next++;
  std::vector<std::array<std::uint8_t, 3>> colours;
  colours.reserve(soup.patches.size());
  for (const int tag : soup.patches) colours.push_back(category_colour(index[tag]));
  std::string keys;
  for (const auto& [tag, i] : index) {
    const auto c = category_colour(i);
    keys += "<span class=\"patch-key\"><span class=\"swatch\" style=\"background:rgb(" + std::to_string(c[0]) + "," +
            std::to_string(c[1]) + "," + std::to_string(c[2]) + ")\"></span>" +
            html::escape(tag_name(soup.patch_names, tag, "patch")) + "</span>\n";
  }
  return "<div class=\"pictures\">\n" + figures(soup, colours, "coloured by boundary patch") + "<figure>" + keys +
         "<figcaption>Faces coloured by boundary patch" + (index.size() > 12 ? " (twelve colours, repeated)" : "") +
         ".</figcaption></figure>\n</div>\n";
}

}  // namespace meshprep
