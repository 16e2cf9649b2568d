// The pipeline with tetrahedralize.order 2: the final tets second-order, their boundary nearer the
// input surface than the linear one, and no tet whose Jacobian is not positive somewhere.
#include "meshprep/core/io.h"
#include "meshprep/pipeline/pipeline.h"
#include "scratch_dir.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>

namespace meshprep {
namespace {

class PipelineSecondOrder : public test::ScratchDirTest {
 protected:
  static PipelineConfig second_order_config() {
    PipelineConfig config;
    config.quality.params.distance_samples = 20000;
    config.tetrahedralize.element_order.order = 2;
    return config;
  }

  // The stage's figures, printed (the acceptance's numbers) and checked.
  static void expect_closer_and_valid(const PipelineResult& r, const std::string& what) {
    ASSERT_TRUE(r.tets && r.second_order && r.tet_quality) << what;
    const SecondOrderRecord& s = *r.second_order;
    std::cout << what << ": Hausdorff to the input / diagonal: linear " << s.hausdorff_linear_relative
              << ", second-order " << s.hausdorff_second_order_relative << "; " << s.quadratic.curved_edges << " of "
              << s.quadratic.boundary_edges << " boundary edges curved, " << s.quadratic.straight_inverting
              << " left straight (a tet would fold), " << s.quadratic.straight_off_reference
              << " (off the surface); smallest scaled Jacobian " << s.quadratic.min_scaled_jacobian << '\n';
    EXPECT_TRUE(r.tets->quadratic()) << what;
    EXPECT_EQ(r.stages.back().name, "second_order") << what;
    EXPECT_LT(s.hausdorff_second_order_relative, s.hausdorff_linear_relative) << what;
    EXPECT_GT(s.quadratic.curved_edges, 0u) << what;
    EXPECT_EQ(s.quadratic.nonpositive_jacobian_tets, 0u) << what;
    EXPECT_GT(s.quadratic.min_scaled_jacobian, 0) << what;
    ASSERT_TRUE(r.tet_quality->quadratic) << what;  // the verdict judges the second-order tets
    EXPECT_EQ(r.tet_quality->quadratic->nonpositive_jacobian_tets, 0u) << what;
  }
};

// The enhancement's remeshing keeps the vertices on the input; its edges cut the input's facets,
// and their nodes go back onto them. (A simplified surface's vertices are off the input, where the
// nodes, on edges, cannot mend the Hausdorff distance: quadratic_test measures against the exact
// sphere instead.)
TEST_F(PipelineSecondOrder, SphereBoundaryCurvesTowardsTheInput) {
  write_soup(test::icosphere(3), path("sphere.off"));
  expect_closer_and_valid(run_pipeline(path("sphere.off"), second_order_config()), "sphere");
}

TEST_F(PipelineSecondOrder, FemurBoundaryCurvesTowardsTheInput) {
  const std::string femur = std::string(MESHPREP_SHARED_DATA_DIR) + "/meshes/femur.off";
  if (!std::filesystem::exists(femur)) GTEST_SKIP() << femur << " not found: ../shared is not beside the clone";
  expect_closer_and_valid(run_pipeline(femur, second_order_config()), "femur");
}

TEST_F(PipelineSecondOrder, OrderOneHasNoSecondOrderStage) {
  PipelineConfig config = second_order_config();
  config.tetrahedralize.element_order.order = 1;
  config.simplify.ratio = 0.5;
  write_soup(test::icosphere(3), path("sphere.off"));
  const PipelineResult r = run_pipeline(path("sphere.off"), config);
  ASSERT_TRUE(r.tets);
  EXPECT_FALSE(r.tets->quadratic());
  EXPECT_FALSE(r.second_order);
  EXPECT_EQ(r.stages.back().name, "improve");
}

}  // namespace
}  // namespace meshprep
