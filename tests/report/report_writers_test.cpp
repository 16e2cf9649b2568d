// The report writers on a hand-built report (independent of analyze_quality).

#include "meshprep/core/errors.h"
#include "meshprep/quality/surface_variation.h"
#include "meshprep/report/report_writers.h"
#include "scratch_dir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace meshprep {
namespace {

namespace fs = std::filesystem;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Two triangles: a right isosceles one and a degenerate one (repeated corner: NaN angles).
TriangleSoup two_triangles() {
  TriangleSoup soup;
  soup.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.5}};
  soup.triangles = {{0, 1, 2}, {1, 3, 3}};
  return soup;
}

TriangleShape right_triangle_shape() {
  TriangleShape s;
  s.radius_ratio = 1.0 / 3.0 + 1;  // not exactly representable: exercises the 9-digit CSV
  s.aspect_ratio = 1.25;
  s.min_angle_deg = 45;
  s.max_angle_deg = 90;
  s.area = 0.5;
  return s;
}

TriangleShape degenerate_shape() {
  TriangleShape s;
  s.radius_ratio = s.aspect_ratio = kInf;
  s.min_angle_deg = s.max_angle_deg = kNaN;
  s.area = 0;
  s.degenerate = true;
  return s;
}

// The distribution of a single value.
Distribution single(double v) { return {v, v, v, v, v, v, 1}; }

QualityReport two_triangle_report() {
  QualityReport r;
  r.path = "two_triangles.off";
  r.vertices = 4;
  r.faces = 2;
  r.edges = 5;
  r.components = 1;
  r.border_edges = 4;
  r.boundary_loops = 1;
  r.euler_characteristic = 1;
  r.degenerate_faces = 1;
  r.self_intersections = 1;
  r.self_intersecting_pairs = {{0, 1}};
  r.area = 0.5;
  r.bbox_diagonal = 1.5;
  r.bbox_max = Vec3(1, 1, 0.5);
  const TriangleShape good = right_triangle_shape();
  r.radius_ratio = single(good.radius_ratio);
  r.aspect_ratio = single(good.aspect_ratio);
  r.min_angle_deg = single(good.min_angle_deg);
  r.max_angle_deg = single(good.max_angle_deg);
  r.area_distribution = single(good.area);
  r.faces_radius_ratio_above_2 = 0;
  r.worst_faces = {{1, degenerate_shape()}, {0, good}};
  r.face_shapes = {good, degenerate_shape()};
  r.time_seconds = 0.25;
  return r;
}

ReferenceComparison reference_comparison() {
  ReferenceComparison c;
  c.path = "reference.off";
  c.hausdorff = 0.0124;
  c.hausdorff_relative = 0.00124;
  c.rms_relative = 0.0002;
  c.mean_relative = 0.0001;
  c.reference_bbox_diagonal = 10;
  c.samples = 1000;
  return c;
}

std::vector<std::string> keys_of(const nlohmann::ordered_json& object) {
  std::vector<std::string> keys;
  for (const auto& item : object.items()) keys.push_back(item.key());
  return keys;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream content;
  content << in.rdbuf();
  return content.str();
}

std::size_t count_occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// A fresh directory per test, removed afterwards.
class ReportFiles : public test::ScratchDirTest {
 protected:
  std::string file(const std::string& name) const { return path(name); }
};

// ---- JSON ------------------------------------------------------------------------------------

TEST(ReportJson, HasTheStableKeysInOrder) {
  const nlohmann::ordered_json j = to_json(two_triangle_report());
  const std::vector<std::string> expected = {
      "file", "vertices", "isolated_vertices", "faces", "edges", "components", "border_edges", "boundary_loops", "non_manifold_edges",
      "non_manifold_vertices", "closed", "manifold", "oriented", "euler_characteristic", "genus",
      "degenerate_faces", "duplicate_faces", "self_intersections", "self_intersections_capped",
      "self_intersecting_pairs", "area", "volume", "bbox_diagonal", "bbox_min", "bbox_max", "radius_ratio",
      "aspect_ratio", "min_angle_deg", "max_angle_deg", "face_area", "faces_min_angle_below_20",
      "faces_min_angle_below_10", "faces_radius_ratio_above_2", "worst_faces", "time_seconds"};
  EXPECT_EQ(keys_of(j), expected);
  const std::vector<std::string> distribution_keys = {"min", "mean", "p5", "p50", "p95", "max"};
  for (const char* key : {"radius_ratio", "aspect_ratio", "min_angle_deg", "max_angle_deg", "face_area"})
    EXPECT_EQ(keys_of(j[key]), distribution_keys) << key;
  const std::vector<std::string> worst_keys = {"index", "radius_ratio", "aspect_ratio", "min_angle_deg",
                                               "max_angle_deg", "area"};
  ASSERT_EQ(j["worst_faces"].size(), 2u);
  EXPECT_EQ(keys_of(j["worst_faces"][0]), worst_keys);
}

TEST(ReportJson, HoldsTheValues) {
  const nlohmann::ordered_json j = to_json(two_triangle_report());
  EXPECT_EQ(j["file"], "two_triangles.off");
  EXPECT_EQ(j["faces"], 2);
  EXPECT_EQ(j["closed"], false);
  EXPECT_EQ(j["euler_characteristic"], 1);
  EXPECT_EQ(j["self_intersecting_pairs"], nlohmann::ordered_json::parse("[[0, 1]]"));
  EXPECT_EQ(j["bbox_max"], nlohmann::ordered_json::parse("[1, 1, 0.5]"));
  EXPECT_DOUBLE_EQ(j["radius_ratio"]["p95"].get<double>(), 4.0 / 3.0);
  EXPECT_DOUBLE_EQ(j["face_area"]["mean"].get<double>(), 0.5);
  EXPECT_EQ(j["worst_faces"][1]["index"], 0);
  EXPECT_DOUBLE_EQ(j["time_seconds"].get<double>(), 0.25);
}

TEST(ReportJson, NonFiniteNumbersAndEmptyOptionalsAreNull) {
  QualityReport r = two_triangle_report();
  r.radius_ratio.max = kInf;
  r.min_angle_deg = {kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, 0};
  const nlohmann::ordered_json j = to_json(r);
  EXPECT_TRUE(j["genus"].is_null());
  EXPECT_TRUE(j["volume"].is_null());
  EXPECT_TRUE(j["radius_ratio"]["max"].is_null());
  for (const auto& item : j["min_angle_deg"].items()) EXPECT_TRUE(item.value().is_null()) << item.key();
  EXPECT_TRUE(j["worst_faces"][0]["radius_ratio"].is_null());  // the degenerate face: inf
  EXPECT_TRUE(j["worst_faces"][0]["min_angle_deg"].is_null());  // NaN
  EXPECT_FALSE(j.contains("reference"));
  EXPECT_FALSE(j.contains("face_shapes"));

  r.genus = 0;
  r.volume = 1.5;
  const nlohmann::ordered_json k = to_json(r);
  EXPECT_EQ(k["genus"], 0);
  EXPECT_DOUBLE_EQ(k["volume"].get<double>(), 1.5);
}

TEST(ReportJson, ReferenceIsPresentWithAllKeysWhenSet) {
  QualityReport r = two_triangle_report();
  r.reference = reference_comparison();
  const nlohmann::ordered_json j = to_json(r);
  const std::vector<std::string> keys = keys_of(j);
  ASSERT_EQ(keys.size(), 36u);
  EXPECT_EQ(keys[34], "reference");
  EXPECT_EQ(keys[35], "time_seconds");
  const std::vector<std::string> expected = {"file", "hausdorff", "hausdorff_relative", "rms_relative",
                                             "mean_relative", "reference_bbox_diagonal", "volume_change_percent",
                                             "samples"};
  EXPECT_EQ(keys_of(j["reference"]), expected);
  EXPECT_EQ(j["reference"]["file"], "reference.off");
  EXPECT_DOUBLE_EQ(j["reference"]["hausdorff"].get<double>(), 0.0124);
  EXPECT_EQ(j["reference"]["samples"], 1000);
  EXPECT_TRUE(j["reference"]["volume_change_percent"].is_null());

  r.reference->volume_change_percent = -2.5;
  EXPECT_DOUBLE_EQ(to_json(r)["reference"]["volume_change_percent"].get<double>(), -2.5);
}

// ---- text summary ----------------------------------------------------------------------------

TEST(ReportText, MentionsTheCountsTopologyAndProblems) {
  std::ostringstream out;
  write_text_summary(out, two_triangle_report());
  const std::string text = out.str();
  EXPECT_NE(text.find("two_triangles.off"), std::string::npos);
  EXPECT_NE(text.find("faces"), std::string::npos);
  EXPECT_NE(text.find("closed"), std::string::npos);
  EXPECT_NE(text.find("!  self-intersections"), std::string::npos) << text;
  EXPECT_NE(text.find("OK duplicate faces"), std::string::npos) << text;
  EXPECT_EQ(text.find("Reference"), std::string::npos);
  EXPECT_EQ(text.find('\x1b'), std::string::npos);  // no colour codes
  bool face_count_shown = false;
  for (const std::string& line : lines_of(text))
    if (line.find("faces") != std::string::npos && line.find(" 2") != std::string::npos) face_count_shown = true;
  EXPECT_TRUE(face_count_shown) << text;
}

TEST(ReportText, StaysShortWithTenWorstFacesAndAReference) {
  QualityReport r = two_triangle_report();
  r.worst_faces.resize(10, r.worst_faces.back());
  r.reference = reference_comparison();
  std::ostringstream out;
  out << std::right << std::setprecision(2);  // the caller's formatting must not leak in
  write_text_summary(out, r);
  const std::string text = out.str();
  EXPECT_LE(lines_of(text).size(), 45u) << text;
  EXPECT_NE(text.find("1.24e-02"), std::string::npos) << text;  // Hausdorff, scientific
  EXPECT_NE(text.find("1.24e-03"), std::string::npos) << text;  // relative
  EXPECT_TRUE(out.flags() & std::ios_base::right);                  // the caller's flags are restored
}

// ---- CSV -------------------------------------------------------------------------------------

TEST_F(ReportFiles, CsvHasAHeaderAndOneRoundTrippingRowPerFace) {
  const TriangleSoup soup = two_triangles();
  const QualityReport report = two_triangle_report();
  write_csv(file("faces.csv"), soup, report);
  const std::vector<std::string> lines = lines_of(read_file(file("faces.csv")));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "face,v0,v1,v2,radius_ratio,aspect_ratio,min_angle_deg,max_angle_deg,area,degenerate");
  EXPECT_EQ(lines[2], "1,1,3,3,inf,inf,nan,nan,0,1");

  std::istringstream row(lines[1]);
  std::vector<double> fields;
  for (std::string field; std::getline(row, field, ',');) fields.push_back(std::strtod(field.c_str(), nullptr));
  ASSERT_EQ(fields.size(), 10u);
  const TriangleShape& s = report.face_shapes[0];
  EXPECT_EQ(fields[0], 0);
  EXPECT_EQ(fields[2], 1);
  EXPECT_NEAR(fields[4], s.radius_ratio, 1e-8 * s.radius_ratio);  // 9 significant digits
  EXPECT_EQ(fields[5], s.aspect_ratio);
  EXPECT_EQ(fields[6], s.min_angle_deg);
  EXPECT_EQ(fields[7], s.max_angle_deg);
  EXPECT_EQ(fields[8], s.area);
  EXPECT_EQ(fields[9], 0);
}

TEST_F(ReportFiles, CsvAndVtkRejectAReportOfAnotherMesh) {
  QualityReport report = two_triangle_report();
  report.face_shapes.pop_back();
  EXPECT_THROW(write_csv(file("faces.csv"), two_triangles(), report), InvalidInput);
  EXPECT_THROW(write_vtk(file("faces.vtk"), two_triangles(), report), InvalidInput);
  EXPECT_FALSE(fs::exists(file("faces.csv")));
  EXPECT_FALSE(fs::exists(file("faces.vtk")));
}

// ---- VTK -------------------------------------------------------------------------------------

// Reads back the legacy binary VTK that write_vtk produces (big-endian data blocks).
class VtkReader {
 public:
  explicit VtkReader(std::string content) : content_(std::move(content)) {}

  std::string line() {
    const std::size_t end = content_.find('\n', pos_);
    if (end == std::string::npos) throw std::runtime_error("VTK: missing line");
    std::string text = content_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return text;
  }

  std::uint64_t big_endian(int bytes) {
    if (pos_ + static_cast<std::size_t>(bytes) > content_.size()) throw std::runtime_error("VTK: truncated");
    std::uint64_t bits = 0;
    for (int i = 0; i < bytes; ++i) bits = bits << 8 | static_cast<unsigned char>(content_[pos_++]);
    return bits;
  }

  double real() {
    const std::uint64_t bits = big_endian(8);
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }

  std::int32_t integer() { return static_cast<std::int32_t>(static_cast<std::uint32_t>(big_endian(4))); }

  bool at_end() const { return pos_ == content_.size(); }

 private:
  std::string content_;
  std::size_t pos_ = 0;
};

TEST_F(ReportFiles, VtkIsBinaryPolydataWithFaceMetricsAndVertexVariation) {
  const TriangleSoup soup = two_triangles();
  const QualityReport report = two_triangle_report();
  write_vtk(file("faces.vtk"), soup, report);
  VtkReader vtk(read_file(file("faces.vtk")));

  EXPECT_EQ(vtk.line(), "# vtk DataFile Version 3.0");
  EXPECT_NE(vtk.line().find("two_triangles.off"), std::string::npos);
  EXPECT_EQ(vtk.line(), "BINARY");
  EXPECT_EQ(vtk.line(), "DATASET POLYDATA");
  ASSERT_EQ(vtk.line(), "POINTS 4 double");
  for (const Vec3& p : soup.points)
    for (int i = 0; i < 3; ++i) EXPECT_EQ(vtk.real(), p[i]);
  EXPECT_EQ(vtk.line(), "");  // the newline after the data
  ASSERT_EQ(vtk.line(), "POLYGONS 2 8");
  for (const Triangle& t : soup.triangles) {
    EXPECT_EQ(vtk.integer(), 3);
    for (std::uint32_t v : t) EXPECT_EQ(vtk.integer(), static_cast<std::int32_t>(v));
  }
  EXPECT_EQ(vtk.line(), "");
  ASSERT_EQ(vtk.line(), "CELL_DATA 2");

  const std::pair<const char*, double TriangleShape::*> metrics[] = {
      {"radius_ratio", &TriangleShape::radius_ratio},   {"aspect_ratio", &TriangleShape::aspect_ratio},
      {"min_angle_deg", &TriangleShape::min_angle_deg}, {"max_angle_deg", &TriangleShape::max_angle_deg},
      {"area", &TriangleShape::area}};
  for (const auto& [name, field] : metrics) {
    ASSERT_EQ(vtk.line(), std::string("SCALARS ") + name + " double 1");
    ASSERT_EQ(vtk.line(), "LOOKUP_TABLE default");
    for (const TriangleShape& s : report.face_shapes) {
      const double v = vtk.real();
      if (std::isnan(s.*field)) {
        EXPECT_TRUE(std::isnan(v)) << name;
      } else {
        EXPECT_EQ(v, s.*field) << name;  // exact, inf included
      }
    }
    EXPECT_EQ(vtk.line(), "");
  }
  ASSERT_EQ(vtk.line(), "SCALARS degenerate int 1");
  ASSERT_EQ(vtk.line(), "LOOKUP_TABLE default");
  EXPECT_EQ(vtk.integer(), 0);
  EXPECT_EQ(vtk.integer(), 1);
  EXPECT_EQ(vtk.line(), "");

  // Every point's 2-ring is all four (non-coplanar) points: one positive sigma for all.
  ASSERT_EQ(vtk.line(), "POINT_DATA 4");
  ASSERT_EQ(vtk.line(), "SCALARS surface_variation double 1");
  ASSERT_EQ(vtk.line(), "LOOKUP_TABLE default");
  for (const double sigma : surface_variation(soup)) {
    EXPECT_GT(sigma, 0.0);
    EXPECT_EQ(vtk.real(), sigma);
  }
  EXPECT_EQ(vtk.line(), "");
  EXPECT_TRUE(vtk.at_end());
}

// ---- HTML ------------------------------------------------------------------------------------

TEST_F(ReportFiles, HtmlIsOneSelfContainedPageWithHistograms) {
  QualityReport report = two_triangle_report();
  report.reference = reference_comparison();
  write_html(file("report.html"), two_triangles(), report);
  const std::string html = read_file(file("report.html"));
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("two_triangles.off"), std::string::npos);
  EXPECT_EQ(count_occurrences(html, "<svg"), 6u);  // one per metric, and the colour legend of the pictures
  // The surface is open (one view), drawn by meshprep as an inline PNG.
  EXPECT_EQ(count_occurrences(html, "<img "), 1u);
  EXPECT_NE(html.find("src=\"data:image/png;base64,iVBORw0KGgo"), std::string::npos);  // the PNG signature
  // Self-contained: nothing fetched.
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  // The degenerate face's infinite ratios are in the overflow bars.
  EXPECT_NE(html.find("&gt;5: 1 faces (1 infinite)"), std::string::npos);
  // Checks: closed fails, no duplicate faces passes.
  EXPECT_NE(html.find("badge fail\">\u2718 closed"), std::string::npos);
  EXPECT_NE(html.find("badge pass\">\u2714 no duplicate faces"), std::string::npos);
  EXPECT_NE(html.find("reference.off"), std::string::npos);
}

TEST_F(ReportFiles, HtmlEscapesTheFileName) {
  QualityReport report = two_triangle_report();
  report.path = "a<b>&c.off";
  write_html(file("report.html"), two_triangles(), report);
  const std::string html = read_file(file("report.html"));
  EXPECT_NE(html.find("a&lt;b&gt;&amp;c.off"), std::string::npos);
  EXPECT_EQ(html.find("a<b>&c.off"), std::string::npos);
}

TEST_F(ReportFiles, HtmlOfAnEmptyReportIsWritten) {
  QualityReport report;  // no faces: every distribution empty
  constexpr Distribution empty{kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, 0};
  report.radius_ratio = report.aspect_ratio = report.min_angle_deg = report.max_angle_deg = empty;
  report.area_distribution = empty;
  EXPECT_NO_THROW(write_html(file("report.html"), TriangleSoup(), report));
  EXPECT_NE(read_file(file("report.html")).find("(in-memory mesh)"), std::string::npos);
}

// ---- errors ----------------------------------------------------------------------------------

TEST_F(ReportFiles, WritersIntoAMissingDirectoryThrowIoError) {
  const TriangleSoup soup = two_triangles();
  const QualityReport report = two_triangle_report();
  const std::string missing = (dir_ / "no_such_directory").string();
  EXPECT_THROW(write_csv(missing + "/faces.csv", soup, report), IoError);
  EXPECT_THROW(write_vtk(missing + "/faces.vtk", soup, report), IoError);
  EXPECT_THROW(write_html(missing + "/report.html", soup, report), IoError);
  EXPECT_FALSE(fs::exists(missing));
}

}  // namespace
}  // namespace meshprep
