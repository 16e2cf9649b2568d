// write_csv and write_vtk: the per-face metrics of a report, for spreadsheets and ParaView; the VTK
// file also holds the per-vertex surface variation, the paper's "curvature analysis" picture.

#include "meshprep/report/report_writers.h"

#include "meshprep/core/atomic_file.h"
#include "meshprep/core/errors.h"
#include "meshprep/quality/surface_variation.h"
#include "meshprep/report/number_format.h"

#include "face_metrics.h"

#include <cstdint>
#include <cstring>
#include <limits>

namespace meshprep {
namespace {

using detail::FaceMetric;
using detail::kFaceMetrics;
using detail::require_one_shape_per_face;

// ---- CSV ------------------------------------------------------------------------------------

std::string csv_header() {
  std::string header = "face,v0,v1,v2";
  for (const FaceMetric& metric : kFaceMetrics) header += std::string(",") + metric.name;
  return header + ",degenerate\n";
}

std::string csv_row(std::size_t face, const Triangle& t, const TriangleShape& shape) {
  std::string row = std::to_string(face);
  for (std::uint32_t v : t) row += ',' + std::to_string(v);
  for (const FaceMetric& metric : kFaceMetrics) row += ',' + format_number(shape.*metric.field, 9);
  row += shape.degenerate ? ",1\n" : ",0\n";
  return row;
}

// ---- VTK (legacy, binary: big-endian whatever the host) ----------------------------------------

void append_big_endian(std::string& buffer, std::uint64_t bits, int bytes) {
  for (int shift = 8 * (bytes - 1); shift >= 0; shift -= 8) buffer += static_cast<char>((bits >> shift) & 0xffu);
}

void append_double(std::string& buffer, double v) {
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);  // bit-exact, so inf and NaN survive
  append_big_endian(buffer, bits, 8);
}

void append_int32(std::string& buffer, std::int32_t v) { append_big_endian(buffer, static_cast<std::uint32_t>(v), 4); }

// VTK legacy binary indices and counts are 32-bit signed integers.
void require_vtk_sizes(const std::string& path, const TriangleSoup& soup) {
  constexpr std::size_t int_max = std::numeric_limits<std::int32_t>::max();
  if (soup.points.size() > int_max || soup.triangles.size() > int_max / 4)
    throw InvalidInput(path + ": the mesh is too large for a legacy VTK file");
}

// The title line: at most 255 characters, no line breaks.
std::string vtk_title(const QualityReport& report) {
  std::string title = "meshprep quality report" + (report.path.empty() ? "" : ": " + report.path);
  for (char& c : title)
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  return title.substr(0, 255);
}

void write_vtk_points(std::ostream& out, const TriangleSoup& soup) {
  std::string data;
  data.reserve(24 * soup.points.size());
  for (const Vec3& p : soup.points)
    for (int i = 0; i < 3; ++i) append_double(data, p[i]);
  out << "POINTS " << soup.points.size() << " double\n" << data << '\n';
}

void write_vtk_polygons(std::ostream& out, const TriangleSoup& soup) {
  std::string data;
  data.reserve(16 * soup.triangles.size());
  for (const Triangle& t : soup.triangles) {
    append_int32(data, 3);
    for (std::uint32_t v : t) append_int32(data, static_cast<std::int32_t>(v));
  }
  out << "POLYGONS " << soup.triangles.size() << ' ' << 4 * soup.triangles.size() << '\n' << data << '\n';
}

// A SCALARS block named `name` holding value(i) for i < count.
template <class Value>
void write_vtk_doubles(std::ostream& out, const char* name, std::size_t count, Value value) {
  std::string data;
  data.reserve(8 * count);
  for (std::size_t i = 0; i < count; ++i) append_double(data, value(i));
  out << "SCALARS " << name << " double 1\nLOOKUP_TABLE default\n" << data << '\n';
}

void write_vtk_metric(std::ostream& out, const FaceMetric& metric, const std::vector<TriangleShape>& shapes) {
  write_vtk_doubles(out, metric.name, shapes.size(), [&](std::size_t f) { return shapes[f].*metric.field; });
}

void write_vtk_degenerate(std::ostream& out, const std::vector<TriangleShape>& shapes) {
  std::string data;
  data.reserve(4 * shapes.size());
  for (const TriangleShape& shape : shapes) append_int32(data, shape.degenerate ? 1 : 0);
  out << "SCALARS degenerate int 1\nLOOKUP_TABLE default\n" << data << '\n';
}

}  // namespace

void write_csv(const std::string& path, const TriangleSoup& soup, const QualityReport& report) {
  require_one_shape_per_face(path, soup, report);
  write_file_atomically(path, [&](std::ostream& out) {
    out << csv_header();
    for (std::size_t f = 0; f < soup.triangles.size(); ++f) out << csv_row(f, soup.triangles[f], report.face_shapes[f]);
  });
}

void write_vtk(const std::string& path, const TriangleSoup& soup, const QualityReport& report) {
  require_one_shape_per_face(path, soup, report);
  require_vtk_sizes(path, soup);
  const std::vector<double> sigma = surface_variation(soup);
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        out << "# vtk DataFile Version 3.0\n" << vtk_title(report) << "\nBINARY\nDATASET POLYDATA\n";
        write_vtk_points(out, soup);
        write_vtk_polygons(out, soup);
        out << "CELL_DATA " << soup.triangles.size() << '\n';
        for (const FaceMetric& metric : kFaceMetrics) write_vtk_metric(out, metric, report.face_shapes);
        write_vtk_degenerate(out, report.face_shapes);
        out << "POINT_DATA " << soup.points.size() << '\n';
        write_vtk_doubles(out, "surface_variation", sigma.size(), [&](std::size_t v) { return sigma[v]; });
      },
      /*binary=*/true);
}

}  // namespace meshprep
