// Second-order meshes through the files: every format that holds 10-node tets writes them and
// (but .inp, which meshprep does not read) reads them back with each node in its place, and
// third-party readers (meshio, Gmsh for Medit) find the node order each format documents.
#include "meshprep/core/errors.h"
#include "meshprep/fem/export.h"
#include "meshprep/fem/import.h"
#include "meshprep/fem/quadratic.h"
#include "meshprep/fem/tet_quality.h"
#include "scratch_dir.h"
#include "tet_test_meshes.h"
#include "third_party_tools.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace meshprep {
namespace {

// cube_tets(2): 48 tets, its edges' nodes straight.
TetMesh straight_cube() {
  TetMesh mesh = test::cube_tets(2);
  make_quadratic(mesh);
  return mesh;
}

// Each mid-edge node moved off its midpoint by its own small amount (a few thousandths of the
// cube's edge, far below what folds a tet): a node read into another place no longer matches.
TetMesh curved_cube() {
  TetMesh mesh = straight_cube();
  const std::size_t corners = test::cube_tets(2).points.size();
  for (std::size_t v = corners; v < mesh.points.size(); ++v) {
    const double k = static_cast<double>(v - corners);
    mesh.points[v] += 1e-3 * Vec3(std::sin(k), std::cos(1.3 * k), std::sin(0.7 * k + 1));
  }
  return mesh;
}

class QuadraticIoTest : public test::ScratchDirTest {};

// The written and read meshes have, tet by tet, the same ten node positions.
void expect_same_nodes(const TetMesh& written, const TetMesh& read, const std::string& file) {
  ASSERT_TRUE(read.quadratic()) << file;
  ASSERT_EQ(read.tets.size(), written.tets.size()) << file;
  const double tolerance = 1e-12;  // of the unit cube: coordinates are written to 17 digits
  for (std::size_t t = 0; t < written.tets.size(); ++t) {
    for (int c = 0; c < 4; ++c)
      ASSERT_LT((read.points[read.tets[t][c]] - written.points[written.tets[t][c]]).norm(), tolerance) << file << " tet " << t;
    for (int e = 0; e < 6; ++e)
      ASSERT_LT((read.points[read.tet_edge_nodes[t][e]] - written.points[written.tet_edge_nodes[t][e]]).norm(), tolerance)
          << file << " tet " << t << " edge " << e;
  }
}

TEST_F(QuadraticIoTest, EveryReadableFormatReadsItsNodesBackInPlace) {
  const TetMesh mesh = curved_cube();
  const std::pair<const char*, TetExportOptions> files[] = {
      {"v41.msh", {MshVersion::V41, false}}, {"v41_binary.msh", {MshVersion::V41, true}},
      {"v22.msh", {MshVersion::V22, false}}, {"v22_binary.msh", {MshVersion::V22, true}},
      {"cube.vtu", {}}, {"cube.vtk", {}}, {"cube.mesh", {}}, {"cube.xdmf", {}}};
  for (const auto& [name, options] : files) {
    write_tet_mesh(mesh, path(name), options);
    expect_same_nodes(mesh, read_tet_mesh(path(name)), name);
  }
}

TEST_F(QuadraticIoTest, QualityOfAReadBackMeshIsThatOfTheSecondOrderTets) {
  const TetMesh mesh = curved_cube();
  write_tet_mesh(mesh, path("cube.msh"));
  const TetQualityReport read = analyze_tet_quality(read_tet_mesh(path("cube.msh")));
  const TetQualityReport written = analyze_tet_quality(mesh);
  ASSERT_TRUE(read.quadratic.has_value());
  EXPECT_NEAR(read.quadratic->min_scaled_jacobian.min, written.quadratic->min_scaled_jacobian.min, 1e-12);
  EXPECT_EQ(read.quadratic->nonpositive_jacobian_tets, 0u);
  EXPECT_EQ(read.quadratic->curved_tets, mesh.tets.size());
}

TEST_F(QuadraticIoTest, TetgenFilesRefuseASecondOrderMesh) {
  try {
    write_tet_mesh(straight_cube(), path("cube.node"));
    FAIL() << "a second-order mesh was written as .node";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("linear tets only"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path("cube.node")));
}

TEST_F(QuadraticIoTest, ThirdPartyReadersFindEachFormatsDocumentedNodeOrder) {
  const std::string python = test::python_with_meshio();
  if (python.empty()) GTEST_SKIP() << "no python3 with meshio and numpy (apt-get install python3-meshio)";
  const TetMesh mesh = straight_cube();  // p2_readback.py tells the edges apart by their midpoints
  write_tet_mesh(mesh, path("v41.msh"));
  write_tet_mesh(mesh, path("v22_binary.msh"), {MshVersion::V22, true});
  for (const char* name : {"cube.vtu", "cube.vtk", "cube.mesh", "cube.inp", "cube.xdmf"}) write_tet_mesh(mesh, path(name));
  EXPECT_TRUE(test::succeeds(python + " " + MESHPREP_P2_READBACK_SCRIPT + " " + dir_.string() + " " +
                             std::to_string(mesh.tets.size())));
}

}  // namespace
}  // namespace meshprep
