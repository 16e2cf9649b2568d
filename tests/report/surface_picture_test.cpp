#include "meshprep/report/surface_picture.h"

#include "meshprep/core/errors.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace meshprep {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

Rgb pixel(const RgbImage& image, int x, int y) {
  const std::size_t i = 3 * (std::size_t(y) * std::size_t(image.width) + std::size_t(x));
  return {image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
}

// Two unit squares, one at z = 0 and one at z = 1, the far one (for a camera above) listed last.
TriangleSoup stacked_squares() {
  TriangleSoup soup = test::merged(test::translated(test::grid(1), Vec3(0, 0, 1)), test::grid(1));
  return soup;
}

TEST(SurfacePicture, TheNearerFaceHidesTheFartherWhateverTheOrder) {
  const TriangleSoup soup = stacked_squares();
  const std::vector<double> values = {3, 3, 1, 1};  // top square bad (red), bottom good (green)
  SurfaceView from_above;
  from_above.direction = -Vec3::UnitZ();
  from_above.width = from_above.height = 40;
  const Rgb top = pixel(render_surface(soup, values, 1, 3, from_above), 20, 20);
  EXPECT_GT(top[0], top[1]);  // red wins: the square at z = 1 is nearer
  SurfaceView from_below = from_above;
  from_below.direction = Vec3::UnitZ();
  const Rgb bottom = pixel(render_surface(soup, values, 1, 3, from_below), 20, 20);
  EXPECT_GT(bottom[1], bottom[0]);  // green wins: the square at z = 0 is nearer
}

TEST(SurfacePicture, TheSurfaceFillsTheImageWithinAWhiteMargin) {
  const TriangleSoup square = test::grid(1);
  SurfaceView view;
  view.width = view.height = 100;
  const RgbImage image = render_surface(square, {1, 1}, 1, 3, view);
  ASSERT_EQ(image.rgb.size(), 3u * 100 * 100);
  EXPECT_EQ(pixel(image, 0, 0), (Rgb{255, 255, 255}));  // the 4 % margin stays white
  EXPECT_EQ(pixel(image, 99, 99), (Rgb{255, 255, 255}));
  const Rgb centre = pixel(image, 50, 50);
  EXPECT_LT(centre[0], 200);  // shaded green, not background
  EXPECT_GT(centre[1], centre[0]);
}

TEST(SurfacePicture, TheColourScaleRunsFromGreenThroughYellowToRed) {
  EXPECT_EQ(quality_colour(1, 1, 3), (Rgb{26, 152, 80}));
  EXPECT_EQ(quality_colour(2, 1, 3), (Rgb{254, 224, 139}));  // the middle stop
  EXPECT_EQ(quality_colour(3, 1, 3), (Rgb{215, 48, 39}));
  EXPECT_EQ(quality_colour(7, 1, 3), quality_colour(3, 1, 3));  // clamped
  EXPECT_EQ(quality_colour(60, 60, 0), (Rgb{26, 152, 80}));      // angles: large is good
  const Rgb undefined = quality_colour(std::nan(""), 1, 3);
  EXPECT_EQ(undefined, quality_colour(INFINITY, 1, 3));  // NaN and a degenerate face's inf alike
  EXPECT_NE(undefined, quality_colour(3, 1, 3));
}

TEST(SurfacePicture, PngHasTheSignatureAndTheSize) {
  RgbImage image;
  image.width = 300;
  image.height = 2;
  image.rgb.assign(3 * 300 * 2, 128);
  const std::vector<std::uint8_t> png = encode_png(image);
  const std::uint8_t signature[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  ASSERT_GT(png.size(), 33u);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(png[std::size_t(i)], signature[i]);
  // IHDR: width and height as big-endian 32-bit numbers at bytes 16 and 20.
  EXPECT_EQ(png[18] << 8 | png[19], 300);
  EXPECT_EQ(png[22] << 8 | png[23], 2);
  image.rgb.pop_back();
  EXPECT_THROW(encode_png(image), InvalidInput);
}

TEST(SurfacePicture, AClosedSurfaceIsSeenFromBothSidesAnOpenOneFromAbove) {
  const std::vector<SurfaceView> closed = report_views(test::icosphere(2), 64, 48);
  ASSERT_EQ(closed.size(), 2u);
  EXPECT_NEAR(closed[0].direction.normalized().dot(closed[1].direction.normalized()), -std::cos(M_PI / 3), 1e-9);
  const std::vector<SurfaceView> open = report_views(test::grid(4), 64, 48);
  ASSERT_EQ(open.size(), 1u);
  EXPECT_LT(open[0].direction.z(), -0.8);  // the grid faces +z: the camera looks down on it, tilted 30 degrees
}

TEST(SurfacePicture, BadArgumentsAreRefused) {
  const TriangleSoup square = test::grid(1);
  SurfaceView view;
  EXPECT_THROW(render_surface(square, {1}, 1, 3, view), InvalidInput);  // one value for two faces
  view.up = view.direction;
  EXPECT_THROW(render_surface(square, {1, 1}, 1, 3, view), InvalidInput);
  view = SurfaceView();
  view.width = 0;
  EXPECT_THROW(render_surface(square, {1, 1}, 1, 3, view), InvalidInput);
}

}  // namespace
}  // namespace meshprep
