// render_surface: an orthographic z-buffer rasteriser (hidden surfaces removed per pixel), drawn
// at twice the resolution and averaged down, and the green-yellow-red quality colour scale.

#include "meshprep/report/surface_picture.h"

#include "meshprep/core/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace meshprep {
namespace {

constexpr int kSupersampling = 2;
constexpr double kMargin = 0.04;          // of the image size, on each side
constexpr double kEdgeWidth = 1.0;        // supersampled pixels either side of an edge
constexpr double kMinEdgedTriangle = 7;   // mean projected edge (final pixels) from which edges are drawn
constexpr double kEdgeShade = 0.6;        // an edge pixel's brightness factor

using Vec2 = Eigen::Vector2d;
using Colour = std::array<double, 3>;
using Rgb = std::array<std::uint8_t, 3>;

// ColorBrewer's RdYlGn, from green (good) to red (bad).
constexpr Colour kScale[] = {{26, 152, 80}, {145, 207, 96}, {254, 224, 139}, {252, 141, 89}, {215, 48, 39}};
// ColorBrewer's RdBu, from blue (low) through near white to red (high).
constexpr Colour kDivergingScale[] = {{33, 102, 172}, {146, 197, 222}, {247, 247, 247}, {244, 165, 130}, {178, 24, 43}};

template <std::size_t stops>
std::array<std::uint8_t, 3> blend(const Colour (&scale)[stops], double fraction) {
  const double s = std::clamp(fraction, 0.0, 1.0) * (stops - 1);
  const int i = std::min(static_cast<int>(stops) - 2, static_cast<int>(s));
  const double f = s - i;
  std::array<std::uint8_t, 3> c{};
  for (int k = 0; k < 3; ++k) c[k] = static_cast<std::uint8_t>(std::lround((1 - f) * scale[i][k] + f * scale[i + 1][k]));
  return c;
}

// The camera frame: x to the right, y up, z towards the viewer.
struct Camera {
  Vec3 right, up, towards;
};

Camera camera_of(const SurfaceView& view) {
  const double length = view.direction.norm();
  if (!(length > 0) || !view.direction.allFinite()) throw InvalidInput("render_surface: the view direction is zero");
  const Vec3 towards = -view.direction / length;
  Vec3 up = view.up - view.up.dot(towards) * towards;
  if (!(up.norm() > 1e-9 * view.up.norm())) throw InvalidInput("render_surface: the up vector is parallel to the view");
  up.normalize();
  return {up.cross(towards), up, towards};
}

// Pixel coordinates (supersampled) and depth of every point; the surface fills the image.
struct Projection {
  std::vector<Vec2> pixels;
  std::vector<double> depth;
  double scale = 1;  // supersampled pixels per model unit
};

Projection project(const TriangleSoup& soup, const Camera& camera, int width, int height) {
  Projection p;
  Eigen::AlignedBox2d box;
  std::vector<Vec2> plane(soup.points.size());
  p.depth.resize(soup.points.size());
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    plane[i] = {soup.points[i].dot(camera.right), soup.points[i].dot(camera.up)};
    p.depth[i] = soup.points[i].dot(camera.towards);
  }
  for (const Triangle& t : soup.triangles)
    for (const std::uint32_t v : t) box.extend(plane[v]);
  const double w = kSupersampling * width, h = kSupersampling * height;
  const Vec2 size = box.isEmpty() ? Vec2(1, 1) : box.sizes().cwiseMax(1e-300);
  p.scale = (1 - 2 * kMargin) * std::min(w / size.x(), h / size.y());
  const Vec2 centre = box.isEmpty() ? Vec2(0, 0) : box.center();
  p.pixels.resize(plane.size());
  for (std::size_t i = 0; i < plane.size(); ++i)  // y grows downwards in the image
    p.pixels[i] = {w / 2 + (plane[i].x() - centre.x()) * p.scale, h / 2 - (plane[i].y() - centre.y()) * p.scale};
  return p;
}

// The mean projected edge length, in final pixels: are the triangles large enough to outline?
double mean_edge_pixels(const TriangleSoup& soup, const Projection& p) {
  double sum = 0;
  for (const Triangle& t : soup.triangles)
    for (int k = 0; k < 3; ++k) sum += (p.pixels[t[(k + 1) % 3]] - p.pixels[t[k]]).norm();
  return soup.triangles.empty() ? 0 : sum / (3.0 * static_cast<double>(soup.triangles.size()) * kSupersampling);
}

// The supersampled image. Its colours are stored as bytes: 11 bytes a sample instead of 32 with
// doubles, which made the report's pictures the peak of a whole pipeline run on a 75 k-face mesh
// (30 of its 79 MB). Rounding each sample moves an averaged pixel by at most one level.
struct Canvas {
  int width, height;
  std::vector<double> depth;
  std::vector<Rgb> colour;
  Canvas(int w, int h)
      : width(w), height(h), depth(std::size_t(w) * std::size_t(h), -std::numeric_limits<double>::infinity()),
        colour(std::size_t(w) * std::size_t(h), Rgb{255, 255, 255}) {}
};

Rgb to_bytes(const Colour& colour, double factor) {
  Rgb rgb{};
  for (int k = 0; k < 3; ++k) rgb[k] = static_cast<std::uint8_t>(std::lround(std::clamp(factor * colour[k], 0.0, 255.0)));
  return rgb;
}

// Fills one triangle: pixel centres inside it (either orientation) whose depth is nearest the viewer.
void fill_triangle(Canvas& canvas, const Vec2 (&q)[3], const double (&z)[3], const Colour& colour, bool outline) {
  const double area = (q[1] - q[0]).x() * (q[2] - q[0]).y() - (q[1] - q[0]).y() * (q[2] - q[0]).x();
  if (!(std::abs(area) > 1e-12)) return;  // seen edge-on
  const int x0 = std::max(0, static_cast<int>(std::floor(std::min({q[0].x(), q[1].x(), q[2].x()}))));
  const int x1 = std::min(canvas.width - 1, static_cast<int>(std::ceil(std::max({q[0].x(), q[1].x(), q[2].x()}))));
  const int y0 = std::max(0, static_cast<int>(std::floor(std::min({q[0].y(), q[1].y(), q[2].y()}))));
  const int y1 = std::min(canvas.height - 1, static_cast<int>(std::ceil(std::max({q[0].y(), q[1].y(), q[2].y()}))));
  double edge_length[3];
  for (int k = 0; k < 3; ++k) edge_length[k] = (q[(k + 2) % 3] - q[(k + 1) % 3]).norm();
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const Vec2 c(x + 0.5, y + 0.5);
      double b[3];  // barycentric coordinates: b[k] is opposite corner k
      for (int k = 0; k < 3; ++k) {
        const Vec2 e = q[(k + 2) % 3] - q[(k + 1) % 3], d = c - q[(k + 1) % 3];
        b[k] = (e.x() * d.y() - e.y() * d.x()) / area;
      }
      if (b[0] < 0 || b[1] < 0 || b[2] < 0) continue;
      const double depth = b[0] * z[0] + b[1] * z[1] + b[2] * z[2];
      const std::size_t i = std::size_t(y) * std::size_t(canvas.width) + std::size_t(x);
      if (depth <= canvas.depth[i]) continue;
      canvas.depth[i] = depth;
      bool on_edge = false;  // distance to edge k = b[k] |area| / |edge k|
      for (int k = 0; k < 3 && outline; ++k) on_edge |= b[k] * std::abs(area) / edge_length[k] < kEdgeWidth;
      canvas.colour[i] = to_bytes(colour, on_edge ? kEdgeShade : 1.0);
    }
}

}  // namespace

std::array<std::uint8_t, 3> quality_colour(double value, double good, double bad) {
  if (!std::isfinite(value) && !(value < 0)) return {120, 0, 20};
  return blend(kScale, (value - good) / (bad - good));
}

std::array<std::uint8_t, 3> diverging_colour(double value, double low, double high) {
  if (std::isnan(value)) return {150, 150, 150};
  return blend(kDivergingScale, (value - low) / (high - low));
}

RgbImage render_surface(const TriangleSoup& soup, const std::vector<double>& face_values, double good, double bad,
                        const SurfaceView& view) {
  if (face_values.size() != soup.triangles.size())
    throw InvalidInput("render_surface: " + std::to_string(face_values.size()) + " values for " +
                       std::to_string(soup.triangles.size()) + " faces");
  std::vector<std::array<std::uint8_t, 3>> colours;
  colours.reserve(face_values.size());
  for (const double value : face_values) colours.push_back(quality_colour(value, good, bad));
  return render_surface(soup, colours, view);
}

std::array<std::uint8_t, 3> category_colour(int index) {
  // Twelve hues that stay apart, dark enough that shading keeps them apart too (ColorBrewer's
  // "Paired" re-ordered so that neighbours in the list differ most).
  static constexpr std::uint8_t kHues[][3] = {{31, 120, 180}, {227, 26, 28},  {51, 160, 44},   {255, 127, 0},
                                              {106, 61, 154}, {177, 89, 40},  {166, 206, 227}, {251, 154, 153},
                                              {178, 223, 138}, {253, 191, 111}, {202, 178, 214}, {255, 255, 153}};
  constexpr int count = sizeof kHues / sizeof kHues[0];
  const auto& c = kHues[((index % count) + count) % count];
  return {c[0], c[1], c[2]};
}

RgbImage render_surface(const TriangleSoup& soup, const std::vector<std::array<std::uint8_t, 3>>& face_colours,
                        const SurfaceView& view) {
  if (face_colours.size() != soup.triangles.size())
    throw InvalidInput("render_surface: " + std::to_string(face_colours.size()) + " colours for " +
                       std::to_string(soup.triangles.size()) + " faces");
  if (view.width < 1 || view.height < 1 || view.width > 8192 || view.height > 8192)
    throw InvalidInput("render_surface: the image must be between 1 x 1 and 8192 x 8192 pixels");
  const Camera camera = camera_of(view);
  const Projection p = project(soup, camera, view.width, view.height);
  const bool outline = mean_edge_pixels(soup, p) >= kMinEdgedTriangle;
  // The light comes from over the viewer's left shoulder; both sides of a face are lit alike.
  const Vec3 light = (camera.towards + 0.4 * camera.up - 0.3 * camera.right).normalized();
  Canvas canvas(kSupersampling * view.width, kSupersampling * view.height);
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    const Vec3 normal = (soup.points[t[1]] - soup.points[t[0]]).cross(soup.points[t[2]] - soup.points[t[0]]);
    const double n = normal.norm();
    const double shade = 0.3 + 0.7 * (n > 0 ? std::abs(normal.dot(light)) / n : 0.0);
    const std::array<std::uint8_t, 3>& base = face_colours[f];
    const Colour colour{shade * base[0], shade * base[1], shade * base[2]};
    const Vec2 q[3] = {p.pixels[t[0]], p.pixels[t[1]], p.pixels[t[2]]};
    const double z[3] = {p.depth[t[0]], p.depth[t[1]], p.depth[t[2]]};
    fill_triangle(canvas, q, z, colour, outline);
  }
  RgbImage image;
  image.width = view.width;
  image.height = view.height;
  image.rgb.resize(std::size_t(3) * std::size_t(view.width) * std::size_t(view.height));
  for (int y = 0; y < view.height; ++y)
    for (int x = 0; x < view.width; ++x)
      for (int k = 0; k < 3; ++k) {
        int sum = 0;
        for (int dy = 0; dy < kSupersampling; ++dy)
          for (int dx = 0; dx < kSupersampling; ++dx)
            sum += canvas.colour[std::size_t(kSupersampling * y + dy) * std::size_t(canvas.width) +
                                 std::size_t(kSupersampling * x + dx)][k];
        image.rgb[3 * (std::size_t(y) * std::size_t(view.width) + std::size_t(x)) + std::size_t(k)] =
            static_cast<std::uint8_t>(std::lround(sum / double(kSupersampling * kSupersampling)));
      }
  return image;
}

}  // namespace meshprep
