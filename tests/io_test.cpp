// Readers, writers, mesh conversion and atomic writes of meshprep::core.
#include "meshprep/core/atomic_file.h"
#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/quality/topology.h"
#include "scratch_dir.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <future>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace meshprep {
namespace {

namespace fs = std::filesystem;

// Each test gets a fresh, empty directory that is removed afterwards.
class IoTest : public test::ScratchDirTest {
 protected:

  std::vector<std::string> directory_entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename().string());
    return names;
  }
};

// A tetrahedron with coordinates that are not exact in binary or in float.
TriangleSoup tetrahedron() {
  TriangleSoup soup;
  soup.points = {{0.1, 0.2, 0.3}, {1.0 / 3.0, 0.0, -2.5e-7}, {0.0, 1.7, 1e5}, {-3.25, 0.5, 0.7}};
  soup.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return soup;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The message of the InvalidInput thrown by `read` (empty if none was thrown).
template <class Read>
std::string invalid_input_message(Read read) {
  try {
    read();
  } catch (const InvalidInput& error) {
    return error.what();
  }
  return {};
}

// Expects read_soup(path) to throw an InvalidInput whose one-line message names the file and
// contains `problem`.
void expect_invalid(const std::string& path, const std::string& problem) {
  const std::string message = invalid_input_message([&] { read_soup(path); });
  ASSERT_FALSE(message.empty()) << path << " was accepted";
  EXPECT_NE(message.find(fs::path(path).filename().string()), std::string::npos) << message;
  EXPECT_NE(message.find(problem), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// Little-endian or big-endian bytes of a value.
template <class T>
std::string bytes_of(T value, bool big_endian = false) {
  std::string bytes(sizeof(T), '\0');
  std::memcpy(bytes.data(), &value, sizeof(T));
  if (big_endian) std::reverse(bytes.begin(), bytes.end());
  return bytes;
}

// ---------------------------------------------------------------------------------------------
// Round trips

struct FormatCase {
  const char* extension;
  bool binary;
  const char* format;
};

class RoundTrip : public IoTest, public ::testing::WithParamInterface<FormatCase> {};

TEST_P(RoundTrip, PreservesTrianglesAndCoordinates) {
  const FormatCase c = GetParam();
  const TriangleSoup soup = tetrahedron();
  const std::string target = path(std::string("mesh.") + c.extension);
  write_soup(soup, target, WriteOptions{c.binary, {}});

  ReadReport report;
  const TriangleSoup back = read_soup(target, &report);
  EXPECT_EQ(report.format, c.format);
  EXPECT_EQ(report.path, target);
  EXPECT_EQ(report.faces_in_file, soup.triangles.size());
  EXPECT_EQ(report.triangles, soup.triangles.size());
  EXPECT_EQ(report.polygons_triangulated, 0u);
  ASSERT_EQ(back.triangles.size(), soup.triangles.size());
  ASSERT_EQ(back.points.size(), soup.points.size());
  const bool is_binary_stl = std::string(c.extension) == "stl" && c.binary;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const Vec3& expected = soup.points[soup.triangles[f][k]];
      const Vec3& actual = back.points[back.triangles[f][k]];
      for (int d = 0; d < 3; ++d) {
        // Binary STL stores float32; the others (ASCII STL too) are written with full precision.
        const double expected_d = is_binary_stl ? static_cast<float>(expected[d]) : expected[d];
        EXPECT_EQ(actual[d], expected_d) << "face " << f << " corner " << k;
      }
    }
  }
  EXPECT_EQ(directory_entries().size(), 1u) << "temporary files left behind";
}

INSTANTIATE_TEST_SUITE_P(AllFormats, RoundTrip,
                         ::testing::Values(FormatCase{"off", false, "off"}, FormatCase{"obj", false, "obj"},
                                           FormatCase{"ply", false, "ply-ascii"}, FormatCase{"ply", true, "ply-binary"},
                                           FormatCase{"stl", false, "stl-ascii"},
                                           FormatCase{"stl", true, "stl-binary"}),
                         [](const auto& test_info) {
                           return std::string(test_info.param.extension) +
                                  (test_info.param.binary ? "_binary" : "_ascii");
                         });

TEST_F(IoTest, WriteMeshAndLoadMeshRoundTrip) {
  const TriMesh mesh = mesh_from_soup(tetrahedron());
  write_mesh(mesh, path("tet.OFF"));
  const LoadedMesh loaded = load_mesh(path("tet.OFF"));
  EXPECT_EQ(loaded.soup.triangles.size(), 4u);
  EXPECT_EQ(loaded.mesh.n_faces(), 4u);
  EXPECT_EQ(loaded.mesh.n_vertices(), 4u);
  EXPECT_TRUE(loaded.build.dropped_faces.empty());
  EXPECT_EQ(loaded.read.format, "off");
  EXPECT_EQ(loaded.soup.points[1], tetrahedron().points[1]);
}

TEST_F(IoTest, WriterRejectsUnknownExtensionAndBadSoup) {
  EXPECT_THROW(write_soup(tetrahedron(), path("mesh.vtk")), InvalidInput);
  EXPECT_THROW(write_soup(tetrahedron(), path("mesh")), InvalidInput);
  TriangleSoup bad = tetrahedron();
  bad.triangles.push_back({0, 1, 4});
  EXPECT_THROW(write_soup(bad, path("bad.off")), InvalidInput);
  EXPECT_TRUE(directory_entries().empty());
}

TEST_F(IoTest, BinaryStlIsSmallAndHasNormals) {
  write_soup(tetrahedron(), path("t.stl"), WriteOptions{true, {}});
  const std::string bytes = read_text(path("t.stl"));
  ASSERT_EQ(bytes.size(), 84u + 50u * 4u);
  EXPECT_NE(bytes.compare(0, 5, "solid"), 0);
  float normal[3];
  std::memcpy(normal, bytes.data() + 84, sizeof normal);
  EXPECT_NEAR(std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]), 1.0, 1e-6);
}

// ---------------------------------------------------------------------------------------------
// Per-vertex scalars

// The tetrahedron's surface variation (all 1/3 for a regular one; these are arbitrary) and a
// second field, values that are not exact in decimal.
std::vector<VertexScalar> two_vertex_scalars() {
  return {{"sigma", {0.0, 1.0 / 3.0, 0.1, 2.5e-17}}, {"quality", {-1.0, 1e300, 0.7, 4.0 / 7.0}}};
}

// The header lines of a PLY file, and where its data starts.
std::vector<std::string> ply_header_lines(const std::string& content, std::size_t& data_offset) {
  const std::string end = "end_header\n";
  data_offset = content.find(end) + end.size();
  std::vector<std::string> lines;
  std::istringstream in(content.substr(0, data_offset));
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

class PlyVertexScalars : public IoTest, public ::testing::WithParamInterface<bool> {};

TEST_P(PlyVertexScalars, FollowTheCoordinatesAndReadBackAsTheSameMesh) {
  const bool binary = GetParam();
  const TriangleSoup soup = tetrahedron();
  WriteOptions options;
  options.binary = binary;
  options.vertex_scalars = two_vertex_scalars();
  write_soup(soup, path("sigma.ply"), options);

  // Our reader skips the extra properties: the geometry is intact.
  const TriangleSoup back = read_soup(path("sigma.ply"));
  EXPECT_EQ(back.points, soup.points);
  EXPECT_EQ(back.triangles, soup.triangles);

  const std::string content = read_text(path("sigma.ply"));
  std::size_t data = 0;
  const std::vector<std::string> header = ply_header_lines(content, data);
  const std::size_t z = std::find(header.begin(), header.end(), "property double z") - header.begin();
  ASSERT_LT(z + 3, header.size());
  EXPECT_EQ(header[z + 1], "property double sigma");
  EXPECT_EQ(header[z + 2], "property double quality");
  EXPECT_EQ(header[z + 3], "element face 4");

  // Each vertex: x y z sigma quality, exactly the doubles given.
  const std::vector<VertexScalar> scalars = two_vertex_scalars();
  std::istringstream text(content.substr(data));
  std::size_t offset = data;
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const double expected[5] = {soup.points[i].x(), soup.points[i].y(), soup.points[i].z(), scalars[0].values[i],
                                scalars[1].values[i]};
    for (const double value : expected) {
      if (binary) {
        EXPECT_EQ(content.substr(offset, 8), bytes_of(value)) << "vertex " << i;
        offset += 8;
      } else {
        std::string token;
        text >> token;
        EXPECT_EQ(std::strtod(token.c_str(), nullptr), value) << "vertex " << i << ": " << token;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AsciiAndBinary, PlyVertexScalars, ::testing::Bool(),
                         [](const auto& test_info) { return std::string(test_info.param ? "binary" : "ascii"); });

TEST_F(IoTest, FormatsWithoutVertexPropertiesDropTheScalars) {
  WriteOptions options;
  options.vertex_scalars = two_vertex_scalars();
  for (const std::string extension : {"off", "obj", "stl"}) {
    write_soup(tetrahedron(), path("plain." + extension));
    write_soup(tetrahedron(), path("scalars." + extension), options);
    EXPECT_EQ(read_text(path("scalars." + extension)), read_text(path("plain." + extension))) << extension;
  }
}

TEST_F(IoTest, InvalidVertexScalarsAreRejectedBeforeWriting) {
  const auto message_for = [&](std::vector<VertexScalar> scalars) {
    WriteOptions options;
    options.vertex_scalars = std::move(scalars);
    try {
      write_soup(tetrahedron(), path("bad.ply"), options);
    } catch (const InvalidInput& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  const std::vector<double> four(4, 0.5);
  EXPECT_NE(message_for({{"sigma", {0.5, 0.5, 0.5}}}).find("3 values for 4 points"), std::string::npos);
  EXPECT_NE(message_for({{"", four}}).find("one printable word"), std::string::npos);
  EXPECT_NE(message_for({{"surface variation", four}}).find("one printable word"), std::string::npos);
  EXPECT_NE(message_for({{"sigma\n", four}}).find("one printable word"), std::string::npos);
  EXPECT_NE(message_for({{"z", four}}).find("other than x, y, z"), std::string::npos);
  EXPECT_NE(message_for({{"sigma", four}, {"sigma", four}}).find("'sigma' twice"), std::string::npos);
  EXPECT_NE(message_for({{"sigma", {0.5, std::nan(""), 0.5, 0.5}}}).find("value 1 is not finite"), std::string::npos);
  EXPECT_NE(message_for({{"sigma", four}, {"q", {}}}).find("bad.ply"), std::string::npos);
  EXPECT_TRUE(directory_entries().empty());
}

// ---------------------------------------------------------------------------------------------
// Polygons and format variants

TEST_F(IoTest, QuadIsTriangulatedInEveryPolygonFormat) {
  const std::string files[] = {
      file("quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"),
      file("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"),
      file("quad.ply",
           "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
           "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"),
  };
  for (const std::string& quad : files) {
    ReadReport report;
    const TriangleSoup soup = read_soup(quad, &report);
    ASSERT_EQ(soup.triangles.size(), 2u) << quad;
    EXPECT_EQ(report.faces_in_file, 1u);
    EXPECT_EQ(report.polygons_triangulated, 1u);
    EXPECT_EQ(report.triangles, 2u);
    EXPECT_EQ(soup.triangles[0], (Triangle{0, 1, 2}));
    EXPECT_EQ(soup.triangles[1], (Triangle{0, 2, 3}));
  }
}

TEST_F(IoTest, OffWithCommentsColoursAndCountsOnHeaderLine) {
  const TriangleSoup soup = read_soup(file("c.off",
                                           "# a comment\nCOFF 3 1 0  # counts here\n\n"
                                           "0 0 0 255 0 0 255\n1 0 0 0 255 0 255 # red\n0 1 0 0 0 255 255\n"
                                           "3 0 1 2 0.5 0.5 0.5\n"));
  ASSERT_EQ(soup.points.size(), 3u);
  EXPECT_EQ(soup.points[1], Vec3(1, 0, 0));
  EXPECT_EQ(soup.triangles.size(), 1u);
}

TEST_F(IoTest, ObjCornerFormsNegativeIndicesAndIgnoredRecords) {
  const std::string obj = file("n.obj",
                               "# exported\nmtllib a.mtl\no thing\ng group\ns off\nusemtl red\n"
                               "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0 1.0\n"
                               "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n"
                               "f 1/1/1 2/2/1 3/3/1\n"
                               "f -4//1 -2//1 -1//1\n"
                               "f 1/1 3/3 4/2\n"
                               "l 1 2\n");
  ReadReport report;
  const TriangleSoup soup = read_soup(obj, &report);
  ASSERT_EQ(soup.triangles.size(), 3u);
  EXPECT_EQ(soup.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(soup.triangles[1], (Triangle{0, 2, 3}));
  EXPECT_EQ(soup.triangles[2], (Triangle{0, 2, 3}));
  EXPECT_EQ(report.faces_in_file, 3u);
}

TEST_F(IoTest, PlyAsciiWithExtraPropertiesAndElements) {
  const std::string ply = file("extra.ply",
                               "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\n"
                               "element vertex 3\r\nproperty float nx\r\nproperty double x\r\nproperty float ny\r\n"
                               "property double y\r\nproperty double z\r\nproperty uchar red\r\n"
                               "property list uchar float weights\r\n"
                               "element face 1\r\nproperty uchar flags\r\nproperty list uchar uint vertex_index\r\n"
                               "element edge 2\r\nproperty int vertex1\r\nproperty int vertex2\r\nend_header\r\n"
                               "0 0.5 0 1 -2 255 2 0.1 0.2\r\n1 1.5 0 2 -3 0 0\r\n0 2.5 1 3 -4 7 1 0\r\n"
                               "9 3 0 1 2\r\n0 1\r\n1 2\r\n");
  ReadReport report;
  const TriangleSoup soup = read_soup(ply, &report);
  EXPECT_EQ(report.format, "ply-ascii");
  ASSERT_EQ(soup.points.size(), 3u);
  EXPECT_EQ(soup.points[0], Vec3(0.5, 1, -2));
  EXPECT_EQ(soup.points[2], Vec3(2.5, 3, -4));
  EXPECT_EQ(soup.triangles, (std::vector<Triangle>{{0, 1, 2}}));
}

// A binary PLY: vertex with int16 x, float y, double z and extra properties, face with an int
// count and ushort indices, preceded by an unrelated element.
std::string binary_ply(bool big_endian, int vertices_announced) {
  const std::string format = big_endian ? "binary_big_endian" : "binary_little_endian";
  std::string data = "ply\nformat " + format + " 1.0\n" +
                     "element material 1\nproperty list uchar char name\n"
                     "element vertex " +
                     std::to_string(vertices_announced) + "\n" +
                     "property short x\nproperty float y\nproperty uchar red\nproperty double z\n"
                     "element face 2\nproperty list int ushort vertex_indices\nproperty float quality\nend_header\n";
  data += bytes_of<std::uint8_t>(2) + "ab";
  const double z[4] = {0.25, -1.5, 3.125, 1e-3};
  for (int v = 0; v < 4; ++v) {
    data += bytes_of<std::int16_t>(static_cast<std::int16_t>(v - 1), big_endian) +
            bytes_of<float>(static_cast<float>(v) * 0.5f, big_endian) + bytes_of<std::uint8_t>(200) +
            bytes_of<double>(z[v], big_endian);
  }
  data += bytes_of<std::int32_t>(3, big_endian) + bytes_of<std::uint16_t>(0, big_endian) +
          bytes_of<std::uint16_t>(1, big_endian) + bytes_of<std::uint16_t>(2, big_endian) +
          bytes_of<float>(1.f, big_endian);
  data += bytes_of<std::int32_t>(4, big_endian);
  for (std::uint16_t i : {0, 2, 3, 1}) data += bytes_of<std::uint16_t>(i, big_endian);
  data += bytes_of<float>(0.5f, big_endian);
  return data;
}

TEST_F(IoTest, PlyBinaryBothByteOrders) {
  for (const bool big_endian : {false, true}) {
    ReadReport report;
    const TriangleSoup soup = read_soup(file("b.ply", binary_ply(big_endian, 4)), &report);
    EXPECT_EQ(report.format, "ply-binary");
    ASSERT_EQ(soup.points.size(), 4u) << big_endian;
    EXPECT_EQ(soup.points[0], Vec3(-1, 0, 0.25));
    EXPECT_EQ(soup.points[3], Vec3(2, 1.5, 1e-3));
    EXPECT_EQ(soup.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}, {0, 3, 1}}));
    EXPECT_EQ(report.faces_in_file, 2u);
    EXPECT_EQ(report.polygons_triangulated, 1u);
  }
}

TEST_F(IoTest, PlyLyingElementCountIsRejected) {
  expect_invalid(file("more.ply", binary_ply(false, 40)), "truncated: header announces 40 vertices");
  expect_invalid(file("fewer.ply", binary_ply(true, 3)), ".ply");
  expect_invalid(
      file("ascii.ply",
           "ply\nformat ascii 1.0\nelement vertex 100\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
      "truncated");
  // Absurd counts are refused without allocating for them.
  expect_invalid(file("huge.ply",
                      "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\nproperty float x\n"
                      "property float y\nproperty float z\nend_header\n" +
                          std::string(24, '\0')),
                 "truncated: header announces 2000000000 vertices, data has 2");
}

TEST_F(IoTest, PlyHeaderErrors) {
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n";
  expect_invalid(file("noz.ply", header + "element face 0\nproperty list uchar int vertex_indices\nend_header\n"),
                 "'z'");
  expect_invalid(file("type.ply", header + "property float128 z\nend_header\n"), "float128");
  expect_invalid(file("noend.ply", header + "property float z\n"), "end_header");
  expect_invalid(file("magic.ply", "plyx\n"), "not a PLY file");
}

TEST_F(IoTest, BinaryStlWhoseHeaderStartsWithSolid) {
  std::string data = "solid but actually binary";
  data.resize(80, ' ');
  data += bytes_of<std::uint32_t>(2);
  const float corners[2][3][3] = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  for (const auto& triangle : corners) {
    data += std::string(12, '\0');  // normal
    for (const auto& corner : triangle) {
      for (const float c : corner) data += bytes_of(c);
    }
    data += bytes_of<std::uint16_t>(0);
  }
  ReadReport report;
  const TriangleSoup soup = read_soup(file("solid.stl", data), &report);
  EXPECT_EQ(report.format, "stl-binary");
  EXPECT_EQ(soup.triangles.size(), 2u);
  EXPECT_EQ(soup.points.size(), 4u) << "equal corners are merged";
  EXPECT_EQ(soup.triangles[1], (Triangle{1, 3, 2}));

  expect_invalid(file("cut.stl", data.substr(0, data.size() - 1)), "truncated binary STL");
}

TEST_F(IoTest, AsciiStlMergesCornersAndChecksSyntax) {
  const std::string facet =
      "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n endloop\nendfacet\n";
  const TriangleSoup soup = read_soup(file("a.stl", "solid x\n" + facet + facet + "endsolid x\n"));
  EXPECT_EQ(soup.points.size(), 3u);
  EXPECT_EQ(soup.triangles.size(), 2u);
  expect_invalid(file("noend.stl", "solid x\n" + facet), "endsolid");
  expect_invalid(file("bad.stl", "solid x\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0\n endloop\n"),
                 "is not a number");
  expect_invalid(file("nan.stl",
                      "solid x\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 nan\n"
                      "  vertex 0 1 0\n endloop\nendfacet\nendsolid\n"),
                 "non-finite");
}

// ---------------------------------------------------------------------------------------------
// Validation

TEST_F(IoTest, TruncatedOff) {
  expect_invalid(file("bunny.off", "OFF\n3 3 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                 "truncated: header announces 3 faces, found 1");
  expect_invalid(file("v.off", "OFF\n5 1 0\n0 0 0\n1 0 0\n"), "truncated: header announces 5 vertices, found 2");
  expect_invalid(file("h.off", "OFF\n"), "truncated");
}

TEST_F(IoTest, NonFiniteCoordinates) {
  expect_invalid(file("x.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"),
                 "vertex 1 has a non-finite coordinate (nan)");
  expect_invalid(file("x.obj", "v 0 0 0\nv 1 0 inf\nv 0 1 0\nf 1 2 3\n"), "non-finite");
  expect_invalid(file("x.ply",
                      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property float z\nend_header\n0 0 0\n1e999 0 0\n0 1 0\n"),
                 "non-finite");
}

TEST_F(IoTest, IndexOutOfRange) {
  expect_invalid(file("x.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"), "out of range");
  const std::string message =
      invalid_input_message([&] { read_soup(file("x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")); });
  EXPECT_NE(message.find("line 4: face index 4 out of range (3 vertices)"), std::string::npos) << message;
  expect_invalid(file("neg.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n"), "out of range");
  expect_invalid(file("x.ply",
                      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                      "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
                 "out of range");
}

TEST_F(IoTest, MalformedFaces) {
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  expect_invalid(file("two.off", "OFF\n3 1 0\n" + vertices + "2 0 1\n"), "at least 3");
  expect_invalid(file("neg.off", "OFF\n3 1 0\n" + vertices + "3 0 -1 2\n"), "negative");
  expect_invalid(file("short.off", "OFF\n3 1 0\n" + vertices + "4 0 1 2\n"), "announces 4 corners");
  expect_invalid(file("garbage.off", "OFF\n3 1 0\n" + vertices + "3 0 1 x2\n"), "'x2'");
  expect_invalid(file("garbage2.off", "OFF\n3 1 0\n0 0 0\n1 0abc 0\n0 1 0\n3 0 1 2\n"), "'0abc'");
  expect_invalid(file("extra.off", "OFF\n3 1 0\n" + vertices + "3 0 1 2\n3 0 1 2\n"), "unexpected content");
  expect_invalid(file("two.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n"), "at least 3");
  expect_invalid(file("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), "index 0");
  expect_invalid(file("slash.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/ 2 3\n"), "'1/'");
  expect_invalid(file("curve.obj", "v 0 0 0\ncurv 0 1 1 2\n"), "unsupported record 'curv'");
  expect_invalid(file("neg.ply",
                      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n" +
                          vertices + "3 0 -1 2\n"),
                 "negative");
}

TEST_F(IoTest, EmptyFilesAndMeshesWithoutFaces) {
  expect_invalid(file("empty.off", ""), "empty file");
  expect_invalid(file("empty.stl", ""), "empty file");
  expect_invalid(file("comments.off", "# nothing\n\n"), "empty file");
  expect_invalid(file("nofaces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"), "no faces");
  expect_invalid(file("nofaces.obj", "v 0 0 0\n"), "no faces");
}

TEST_F(IoTest, UnknownExtensionAndMissingFile) {
  expect_invalid(file("mesh.vtk", "whatever"), "supported: .off, .obj, .ply, .stl");
  expect_invalid(file("noextension", "OFF\n"), "supported");
  try {
    read_soup(path("missing.off"));
    FAIL() << "no exception";
  } catch (const IoError& error) {
    EXPECT_EQ(std::string(error.what()), path("missing.off") + ": cannot open: No such file or directory");
  }
  EXPECT_THROW(read_points(path("missing.xyz")), IoError);
}

TEST_F(IoTest, ExtensionOf) {
  EXPECT_EQ(extension_of("a/B.OFF"), "off");
  EXPECT_EQ(extension_of("dir.d/file"), "");
  EXPECT_EQ(extension_of("x.tar.PLY"), "ply");
}

// ---------------------------------------------------------------------------------------------
// XYZ points

TEST_F(IoTest, XyzThreeAndSixColumns) {
  const PointSet three = read_points(file("p.xyz", "# header\n0 0 0\n\n1.5 -2 3e2  # trailing comment\n"));
  ASSERT_EQ(three.points.size(), 2u);
  EXPECT_EQ(three.points[1], Vec3(1.5, -2, 300));
  EXPECT_TRUE(three.normals.empty());

  const PointSet six = read_points(file("n.xyz", "0 0 0 0 0 1\n1 1 1 0 1 0\n"));
  ASSERT_EQ(six.points.size(), 2u);
  ASSERT_EQ(six.normals.size(), 2u);
  EXPECT_EQ(six.normals[1], Vec3(0, 1, 0));
}

TEST_F(IoTest, XyzErrorsNameTheLine) {
  const auto message = [&](const std::string& name, const std::string& content) {
    return invalid_input_message([&] { read_points(file(name, content)); });
  };
  EXPECT_NE(message("four.xyz", "0 0 0\n# c\n1 2 3 4\n").find("four.xyz: line 3: 4 values"), std::string::npos);
  EXPECT_NE(message("mixed.xyz", "0 0 0\n1 1 1 0 0 1\n").find("line 2"), std::string::npos);
  EXPECT_NE(message("nan.xyz", "0 0 0\n1 nan 0\n").find("line 2: non-finite"), std::string::npos);
  EXPECT_NE(message("word.xyz", "0 0 0\n1 a 0\n").find("line 2: 'a' is not a number"), std::string::npos);
  EXPECT_NE(message("none.xyz", "# only a comment\n").find("no points"), std::string::npos);
  EXPECT_NE(message("empty.xyz", "").find("empty"), std::string::npos);
  EXPECT_NE(message("mesh.off", "OFF\n0 0 0\n").find("mesh.off: a surface mesh (.off), not a point set"),
            std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// Mesh conversion

TEST_F(IoTest, NonManifoldFinFaceIsDroppedAndReported) {
  TriangleSoup fin;
  fin.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {5, 5, 5}};
  fin.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};  // three faces on the edge 0-1
  MeshBuildReport report;
  const TriMesh mesh = mesh_from_soup(fin, &report);
  EXPECT_EQ(report.dropped_faces, (std::vector<std::size_t>{2}));
  EXPECT_EQ(mesh.n_faces(), 2u);
  EXPECT_EQ(mesh.n_vertices(), 6u) << "unreferenced soup points are kept";
  EXPECT_EQ(to_eigen(mesh.point(TriMesh::VertexHandle(5))), Vec3(5, 5, 5));
}

TEST_F(IoTest, RepeatedIndexFaceIsDropped) {
  TriangleSoup soup = tetrahedron();
  soup.triangles.push_back({1, 1, 2});
  MeshBuildReport report;
  const TriMesh mesh = mesh_from_soup(soup, &report);
  EXPECT_EQ(report.dropped_faces, (std::vector<std::size_t>{4}));
  EXPECT_EQ(mesh.n_faces(), 4u);
}

// `meshprep quality` builds the halfedge mesh to list the faces it would drop only when the soup
// is not manifold, oriented and free of duplicates: OpenMesh must then keep every face, whatever
// the order they come in (closed, with a handle, with a border).
TEST_F(IoTest, AManifoldOrientedSoupBuildsWholeInAnyFaceOrder) {
  std::mt19937 rng(7);
  for (TriangleSoup soup : {test::icosphere(2), test::torus(12, 8), test::grid(10)}) {
    for (int order = 0; order < 20; ++order) {
      std::shuffle(soup.triangles.begin(), soup.triangles.end(), rng);
      const Topology topology = analyze_topology(soup);
      ASSERT_TRUE(topology.manifold && topology.oriented && topology.duplicate_faces == 0);
      MeshBuildReport report;
      const TriMesh mesh = mesh_from_soup(soup, &report);
      EXPECT_TRUE(report.dropped_faces.empty()) << order;
      EXPECT_EQ(mesh.n_faces(), soup.triangles.size());
    }
  }
}

TEST_F(IoTest, DroppedFacesAreExplained) {
  const auto first_problem = [](const TriangleSoup& soup) {
    MeshBuildReport report;
    mesh_from_soup(soup, &report);
    return dropped_faces_problem(soup, report);
  };
  TriangleSoup repeated = tetrahedron(), duplicate = tetrahedron(), flipped = tetrahedron(), bowtie = tetrahedron();
  repeated.triangles.push_back({1, 1, 2});
  duplicate.triangles.push_back(duplicate.triangles[1]);
  flipped.triangles[3] = {1, 3, 2};
  bowtie.points.insert(bowtie.points.end(), {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}});  // a second tet at vertex 0
  bowtie.triangles.insert(bowtie.triangles.end(), {{0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6}});
  EXPECT_EQ(first_problem(tetrahedron()), "");
  EXPECT_EQ(first_problem(repeated), "face 4 has two corners at vertex 1");
  EXPECT_EQ(first_problem(duplicate), "face 4 repeats face 1");
  EXPECT_EQ(first_problem(flipped), "face 3 is oriented against face 0 (both run from vertex 2 to 1)");
  EXPECT_EQ(first_problem(bowtie),
            "face 4 makes vertex 0 non-manifold (2 fans of faces meet there) (2 more faces cannot be added either)");
  TriangleSoup fin;
  fin.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fin.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  EXPECT_EQ(first_problem(fin), "face 2 makes the edge 0-1 non-manifold (3 faces share it)");
}

TEST_F(IoTest, SoupFromMeshSkipsDeletedElements) {
  TriMesh mesh = mesh_from_soup(tetrahedron());
  mesh.delete_vertex(TriMesh::VertexHandle(3));  // removes the three faces around it
  const TriangleSoup soup = soup_from_mesh(mesh);
  ASSERT_EQ(soup.points.size(), 3u);
  ASSERT_EQ(soup.triangles.size(), 1u);
  const Triangle t = soup.triangles[0];
  EXPECT_TRUE(t == (Triangle{0, 2, 1}) || t == (Triangle{2, 1, 0}) || t == (Triangle{1, 0, 2})) << t[0] << t[1] << t[2];
  EXPECT_EQ(soup.points[2], tetrahedron().points[2]);
}

// ---------------------------------------------------------------------------------------------
// Atomic writes

TEST_F(IoTest, FailingWriterLeavesNothingBehind) {
  const std::string target = path("out.off");
  EXPECT_THROW(write_file_atomically(target,
                                     [](std::ostream& out) {
                                       out << "partial";
                                       throw std::runtime_error("writer failed");
                                     }),
               std::runtime_error);
  EXPECT_TRUE(directory_entries().empty());

  file("out.off", "old content");
  EXPECT_THROW(write_file_atomically(target,
                                     [](std::ostream& out) {
                                       out << "new";
                                       throw std::runtime_error("writer failed");
                                     }),
               std::runtime_error);
  EXPECT_EQ(read_text(target), "old content");
  EXPECT_EQ(directory_entries(), (std::vector<std::string>{"out.off"}));

  write_file_atomically(target, [](std::ostream& out) { out << "new content"; });
  EXPECT_EQ(read_text(target), "new content");
  EXPECT_EQ(directory_entries().size(), 1u);
}

TEST_F(IoTest, StreamFailureBecomesIoError) {
  const std::string target = path("s.off");
  EXPECT_THROW(write_file_atomically(target, [](std::ostream& out) { out.setstate(std::ios::badbit); }), IoError);
  EXPECT_TRUE(directory_entries().empty());
}

TEST_F(IoTest, WritePathAtomicallyUsesTemporaryWithSameExtension) {
  const std::string target = path("mesh.ply");
  std::string seen;
  write_path_atomically(target, [&](const std::string& temporary) {
    seen = temporary;
    std::ofstream(temporary) << "data";
  });
  EXPECT_EQ(fs::path(seen).parent_path(), dir_);
  EXPECT_EQ(fs::path(seen).extension(), ".ply");
  EXPECT_EQ(fs::path(seen).filename().string().rfind(".mesh.ply.tmp-", 0), 0u) << seen;
  EXPECT_EQ(read_text(target), "data");
  EXPECT_THROW(write_path_atomically(target,
                                     [](const std::string& temporary) {
                                       std::ofstream(temporary) << "partial";
                                       throw std::runtime_error("third party failed");
                                     }),
               std::runtime_error);
  EXPECT_EQ(read_text(target), "data");
  EXPECT_EQ(directory_entries().size(), 1u);
}

TEST_F(IoTest, WritingIntoMissingDirectoryNamesThePath) {
  const std::string target = path("no/such/dir/out.off");
  try {
    write_soup(tetrahedron(), target);
    FAIL() << "no exception";
  } catch (const IoError& error) {
    EXPECT_NE(std::string(error.what()).find(target + ": cannot write"), std::string::npos) << error.what();
  }
}

// ---------------------------------------------------------------------------------------------
// Special files (issue 30): outputs that are not regular files are written, not replaced; inputs
// that are not regular files are refused at once.

bool is_fifo(const std::string& p) { return fs::is_fifo(fs::symlink_status(p)); }

TEST_F(IoTest, AFifoAsOutputIsWrittenNotReplaced) {
  const std::string fifo = path("out.off");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // The reader opens the FIFO as a shell's `cat fifo` would; the write blocks until it does.
  std::future<std::string> read = std::async(std::launch::async, [&] { return read_text(fifo); });
  write_soup(tetrahedron(), fifo);
  const std::string received = read.get();
  EXPECT_TRUE(is_fifo(fifo)) << "the FIFO was replaced";
  EXPECT_EQ(received.rfind("OFF", 0), 0u) << received;
  EXPECT_EQ(directory_entries(), (std::vector<std::string>{"out.off"})) << "a temporary file is left";
}

TEST_F(IoTest, ASymlinkToADeviceStaysALinkAndTheDeviceStaysADevice) {
  const std::string link = path("null.json");
  fs::create_symlink("/dev/null", link);
  write_file_atomically(link, [](std::ostream& out) { out << "{}\n"; });
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_EQ(directory_entries(), (std::vector<std::string>{"null.json"}));
}

TEST_F(IoTest, ASymlinkToAFileStaysALinkAndTheFileIsReplaced) {
  const std::string target = file("real.off", "old");
  const std::string link = path("link.off");
  fs::create_symlink("real.off", link);  // relative, as users make them
  write_soup(tetrahedron(), link);
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read_soup(target).points.size(), 4u);
  std::vector<std::string> entries = directory_entries();
  std::sort(entries.begin(), entries.end());
  EXPECT_EQ(entries, (std::vector<std::string>{"link.off", "real.off"}));
}

TEST_F(IoTest, AFullDeviceIsAWriteErrorNamingTheFile) {
  if (!fs::is_character_file("/dev/full")) GTEST_SKIP() << "no /dev/full";
  // Through a link: a writer that renames over its target replaces the link, never /dev/full.
  const std::string full = path("full.json");
  fs::create_symlink("/dev/full", full);
  try {
    write_file_atomically(full, [](std::ostream& out) { out << std::string(1 << 20, 'x'); });
    FAIL() << "no exception";
  } catch (const WriteError& e) {
    EXPECT_NE(std::string(e.what()).find("full.json: cannot write: No space left on device"), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(fs::is_symlink(full));
}

TEST_F(IoTest, InputsThatAreNotRegularFilesAreRefusedAtOnce) {
  // A FIFO nobody writes to would block the open for ever; a link to /dev/zero would be read until
  // memory runs out.
  const std::string fifo = path("points.xyz");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(invalid_input_message([&] { read_points(fifo); }).find("points.xyz: not a regular file (a FIFO)"),
            std::string::npos);
  fs::create_symlink("/dev/zero", path("zero.off"));
  EXPECT_NE(invalid_input_message([&] { read_soup(path("zero.off")); }).find("zero.off: not a regular file (a character device)"),
            std::string::npos);
  fs::create_directory(path("folder.stl"));
  EXPECT_NE(invalid_input_message([&] { read_soup(path("folder.stl")); }).find("folder.stl: a folder, not a mesh file"),
            std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// Coordinates whose products overflow (issue 30): refused on reading, whatever the format.

TEST_F(IoTest, CoordinatesSpanningMoreThanTheStagesCanMultiplyAreRefused) {
  const std::string off = "OFF\n3 1 0\n-1e300 0 0\n1e300 0 0\n0 1 0\n3 0 1 2\n";
  const std::string message = invalid_input_message([&] { read_soup(file("huge.off", off)); });
  EXPECT_NE(message.find("huge.off: the coordinates span 2e+300 along x, more than 2.38e+51"), std::string::npos) << message;
  // The difference itself overflows: the span is infinite.
  const std::string overflow = "OFF\n3 1 0\n0 -1.7e308 0\n0 1.7e308 0\n1 0 0\n3 0 1 2\n";
  EXPECT_NE(invalid_input_message([&] { read_soup(file("overflow.off", overflow)); }).find("span inf along y"),
            std::string::npos);
  EXPECT_NE(invalid_input_message([&] { read_points(file("huge.xyz", "0 0 0\n0 0 1e60\n")); }).find("along z"),
            std::string::npos);
  // Far from the origin but smaller is fine (the stages move it next to the origin): a span of 1e50,
  // whose sixth power is still a double.
  EXPECT_NO_THROW(read_soup(file("far.off", "OFF\n3 1 0\n1e60 0 0\n1.0000000001e60 0 0\n1e60 1e50 0\n3 0 1 2\n")));
  EXPECT_NO_THROW(read_points(file("large.xyz", "0 0 0\n1e50 0 0\n")));
}

}  // namespace
}  // namespace meshprep
