#pragma once
/// \file surface_picture.h
/// Pictures of a surface drawn by meshprep itself, so that a report shows the mesh without a
/// viewer: an orthographic z-buffer rendering (hidden surfaces removed exactly, per pixel), each
/// face coloured by a per-face value and shaded by its angle to the light, edges drawn where the
/// triangles are large enough to tell apart, 2 x 2 supersampled.

#include "meshprep/core/mesh.h"
#include "meshprep/quality/report.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace meshprep {

struct SurfaceView {
  Vec3 direction = -Vec3::UnitZ();  ///< the direction the camera looks in (any length > 0)
  Vec3 up = Vec3::UnitY();          ///< drawn upwards (its part orthogonal to the direction)
  int width = 640, height = 480;    ///< pixels
};

struct RgbImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  ///< row by row from the top, 3 bytes a pixel
};

/// The colour of `value` on the quality scale from `good` (green) through yellow to `bad` (red);
/// NaN and +inf are dark red. Works either way round (good > bad for angles).
std::array<std::uint8_t, 3> quality_colour(double value, double good, double bad);

/// The colour of `value` on a diverging scale: blue at `low` (and under), near white half-way, red
/// at `high` (and over); NaN grey.
std::array<std::uint8_t, 3> diverging_colour(double value, double low, double high);

/// Render `soup` on a white background, face f coloured by quality_colour(face_values[f], good,
/// bad), the surface scaled to fit the image with a margin.
/// \throws InvalidInput if face_values has the wrong size, the view is degenerate (direction and
///         up parallel, or zero), the image is empty or larger than 8192 x 8192.
RgbImage render_surface(const TriangleSoup& soup, const std::vector<double>& face_values, double good, double bad,
                        const SurfaceView& view);

/// Render `soup` with face f in face_colours[f] (shaded), as above.
/// \throws InvalidInput as above, for face_colours of the wrong size.
RgbImage render_surface(const TriangleSoup& soup, const std::vector<std::array<std::uint8_t, 3>>& face_colours,
                        const SurfaceView& view);

/// The colour of the index-th category (a patch): twelve distinct hues, repeated beyond.
std::array<std::uint8_t, 3> category_colour(int index);

/// The image as a PNG file's bytes (libpng).
std::vector<std::uint8_t> encode_png(const RgbImage& image);

/// The views a report shows: the surface's principal axes decide them (the longest drawn across,
/// the camera along the shortest, tilted by 30 degrees about the longest); a closed surface is
/// seen from both sides, an open one from the side its faces look to.
std::vector<SurfaceView> report_views(const TriangleSoup& soup, int width, int height);

/// The report's pictures of `soup` coloured by radius ratio (report.face_shapes), as an HTML
/// fragment: inline PNG images (data URIs) with a caption and the colour legend.
std::string surface_picture_html(const TriangleSoup& soup, const QualityReport& report);

/// The pictures of `soup` coloured by face_ratios[f], a face's edge length over the size field's
/// h (blue finer than asked, white as asked, red coarser; a log scale from 1/2 to 2), with the
/// legend, as an HTML fragment; empty when the sizes do not match the faces.
std::string size_ratio_picture_html(const TriangleSoup& soup, const std::vector<double>& face_ratios);

/// The pictures of `soup` coloured by boundary patch (soup.patches), with a legend naming each
/// patch, as an HTML fragment; empty when the surface has no patches.
std::string patch_picture_html(const TriangleSoup& soup);

}  // namespace meshprep
