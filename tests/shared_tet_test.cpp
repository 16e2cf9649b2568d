// TetGen on the shared meshes (../shared/data/meshes), against ../shared/anchors.md: the closed
// meshes TetGen accepts must succeed with the tets filling exactly the surface's volume; for the
// others the readiness check must name the real cause. Skipped when ../shared is absent.
#include "meshprep/core/io.h"
#include "meshprep/fem/readiness.h"
#include "meshprep/fem/tet_quality.h"
#include "meshprep/fem/tetrahedralize.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace meshprep;

namespace {

std::string shared_mesh(const std::string& name) {
  return std::string(MESHPREP_SHARED_DATA_DIR) + "/meshes/" + name;
}

struct AcceptedMesh {
  const char* file;
  std::size_t anchor_tets;  // `tetgen -pq1.414` on this machine (anchors.md)
};
void PrintTo(const AcceptedMesh& m, std::ostream* os) { *os << m.file; }

class TetgenAccepts : public ::testing::TestWithParam<AcceptedMesh> {};

struct RejectedMesh {
  const char* file;
  std::size_t border_edges;        // from the judge
  std::size_t self_intersections;  // from the judge
};
void PrintTo(const RejectedMesh& m, std::ostream* os) { *os << m.file; }

class TetgenRejects : public ::testing::TestWithParam<RejectedMesh> {};

}  // namespace

TEST_P(TetgenAccepts, FillsTheSurfaceVolume) {
  const std::string path = shared_mesh(GetParam().file);
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found: ../shared is not beside the clone";
  const TriangleSoup surface = read_soup(path);
  ASSERT_TRUE(check_fem_readiness(surface).ready());
  const TetMesh tets = tetrahedralize_plc(plc_from_surface(surface), TetParams{});
  const TetQualityReport q = analyze_tet_quality(tets);
  double six_v = 0;
  for (const Triangle& t : surface.triangles)
    six_v += surface.points[t[0]].dot(surface.points[t[1]].cross(surface.points[t[2]]));
  // TetGen's Steiner points on the facets are rounded to double, which moves the boundary by
  // ~1e-7 of the volume on these meshes (on exactly planar facets, as in the cube test, or with
  // --keep-surface the volumes agree to round-off).
  EXPECT_NEAR(q.volume, six_v / 6.0, 1e-6 * six_v / 6.0);
  EXPECT_EQ(q.inverted_tets, 0u);
  // Same switches as the anchor's command line: the same mesh up to TetGen's determinism.
  EXPECT_NEAR(static_cast<double>(q.tetrahedra), static_cast<double>(GetParam().anchor_tets), 0.02 * GetParam().anchor_tets);
}

INSTANTIATE_TEST_SUITE_P(Anchors, TetgenAccepts,
                         ::testing::Values(AcceptedMesh{"elephant.off", 52860}, AcceptedMesh{"fandisk.off", 85493},
                                           AcceptedMesh{"femur.off", 204000}, AcceptedMesh{"turbine.off", 149000}),
                         [](const auto& param_info) { return std::string(param_info.param.file).substr(0, 5); });

TEST_P(TetgenRejects, ReadinessNamesTheCause) {
  const std::string path = shared_mesh(GetParam().file);
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found: ../shared is not beside the clone";
  const Readiness r = check_fem_readiness(read_soup(path));
  ASSERT_FALSE(r.ready());
  std::size_t border = 0, intersections = 0;
  for (const ReadinessProblem& p : r.problems) {
    if (p.check == "closed") border = p.count;
    if (p.check == "self_intersections") intersections = p.count;
  }
  EXPECT_EQ(border, GetParam().border_edges);
  EXPECT_EQ(intersections, GetParam().self_intersections);
}

INSTANTIATE_TEST_SUITE_P(Anchors, TetgenRejects,
                         ::testing::Values(RejectedMesh{"ChineseDragon-10kv.off", 6, 38}, RejectedMesh{"horizons.off", 160, 0},
                                           RejectedMesh{"three_peaks.off", 141, 0}, RejectedMesh{"blade.off", 240, 0}),
                         [](const auto& param_info) { return std::string(param_info.param.file).substr(0, 5); });
