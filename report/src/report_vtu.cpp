// write_vtu: the surface with its per-face metrics as cell data and the surface variation as point
// data, in VTK's XML unstructured-grid format (ParaView, meshio). Arrays are inline binary
// (base64 of a UInt64 byte count followed by the little-endian values), so inf and NaN survive.

#include "meshprep/report/report_writers.h"

#include "meshprep/core/atomic_file.h"
#include "meshprep/quality/surface_variation.h"

#include "base64.h"
#include "face_metrics.h"

#include <cstdint>
#include <cstring>

namespace meshprep {
namespace {

constexpr int kVtkTriangle = 5;

class LittleEndian {
 public:
  explicit LittleEndian(std::size_t values) { bytes_.reserve(8 + 8 * values); }
  template <class T>
  void put(T value) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof value);
    for (std::size_t i = 0; i < sizeof value; ++i) bytes_.push_back(static_cast<std::uint8_t>(bits >> (8 * i)));
  }
  // The array as VTK reads it: the payload's size, then the payload.
  std::string encoded() const {
    std::vector<std::uint8_t> framed;
    framed.reserve(8 + bytes_.size());
    for (int i = 0; i < 8; ++i) framed.push_back(static_cast<std::uint8_t>(std::uint64_t(bytes_.size()) >> (8 * i)));
    framed.insert(framed.end(), bytes_.begin(), bytes_.end());
    return detail::base64(framed);
  }

 private:
  std::vector<std::uint8_t> bytes_;
};

void data_array(std::ostream& out, const char* type, const std::string& name, int components, const LittleEndian& data) {
  out << "<DataArray type=\"" << type << "\" Name=\"" << name << "\" NumberOfComponents=\"" << components
      << "\" format=\"binary\">\n" << data.encoded() << "\n</DataArray>\n";
}

void write_document(std::ostream& out, const TriangleSoup& soup, const QualityReport& report,
                    const std::vector<double>& sigma) {
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
         "<UnstructuredGrid>\n<Piece NumberOfPoints=\""
      << soup.points.size() << "\" NumberOfCells=\"" << soup.triangles.size() << "\">\n<Points>\n";
  LittleEndian points(3 * soup.points.size());
  for (const Vec3& p : soup.points)
    for (int i = 0; i < 3; ++i) points.put(p[i]);
  data_array(out, "Float64", "Points", 3, points);
  out << "</Points>\n<Cells>\n";
  LittleEndian connectivity(3 * soup.triangles.size()), offsets(soup.triangles.size()), types(soup.triangles.size());
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    for (const std::uint32_t v : soup.triangles[f]) connectivity.put(static_cast<std::int64_t>(v));
    offsets.put(static_cast<std::int64_t>(3 * (f + 1)));
    types.put(static_cast<std::uint8_t>(kVtkTriangle));
  }
  data_array(out, "Int64", "connectivity", 1, connectivity);
  data_array(out, "Int64", "offsets", 1, offsets);
  data_array(out, "UInt8", "types", 1, types);
  out << "</Cells>\n<CellData Scalars=\"radius_ratio\">\n";
  for (const detail::FaceMetric& metric : detail::kFaceMetrics) {
    LittleEndian values(report.face_shapes.size());
    for (const TriangleShape& shape : report.face_shapes) values.put(shape.*metric.field);
    data_array(out, "Float64", metric.name, 1, values);
  }
  LittleEndian degenerate(report.face_shapes.size());
  for (const TriangleShape& shape : report.face_shapes) degenerate.put(static_cast<std::int32_t>(shape.degenerate));
  data_array(out, "Int32", "degenerate", 1, degenerate);
  out << "</CellData>\n<PointData Scalars=\"surface_variation\">\n";
  LittleEndian variation(sigma.size());
  for (const double s : sigma) variation.put(s);
  data_array(out, "Float64", "surface_variation", 1, variation);
  out << "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace

void write_vtu(const std::string& path, const TriangleSoup& soup, const QualityReport& report) {
  detail::require_one_shape_per_face(path, soup, report);
  const std::vector<double> sigma = surface_variation(soup);
  write_file_atomically(path, [&](std::ostream& out) { write_document(out, soup, report, sigma); });
}

}  // namespace meshprep
