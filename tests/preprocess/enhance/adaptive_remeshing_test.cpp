// The remeshing's own loop (adaptive_remeshing.h), below the enhancement's guards: how it bounds
// its work on a CAD tessellation (issue 48's repair suite found it running for minutes).
#include "enhance/adaptive_remeshing.h"

#include "enhance/sizing_field.h"
#include "enhance/surface_constraints.h"

#include "meshprep/core/io.h"
#include "meshprep/core/mesh.h"
#include "meshprep/preprocess/enhance/enhance.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/surface_distance.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>

using namespace meshprep;
using namespace meshprep::detail;

namespace {

// The rules as the enhancement sets them for its default bound (2e-3 of the diagonal: a quarter
// of it for the chords, 0.35 for the remeshing's moves), the splits unbounded.
struct Remeshing {
  explicit Remeshing(const TriangleSoup& soup)
      : reference(soup), mesh(mesh_from_soup(soup)),
        constraints(mesh, reference, EnhanceParams{}.feature_angle_deg, true),
        sizing(mesh, constraints, sizing_rules(mesh)) {
    rules.max_deviation = 0.35 * bound();
  }
  double bound() const { return 2e-3 * bbox_diagonal(reference); }
  SizingRules sizing_rules(const TriMesh& m) const {
    SizingRules r;
    r.chord_tolerance = 0.25 * bound();
    r.max_faces = std::max<std::size_t>(50000, 10 * m.n_faces());
    return r;
  }
  TriangleSoup reference;
  TriMesh mesh;
  SurfaceConstraints constraints;
  SizingField sizing;
  RemeshRules rules;
};

}  // namespace

TEST(AdaptiveRemeshing, ARemeshingThatRunsAwayEndsAtTheTimeLimit) {
  // The cones of this part are fans of needles from an apex to a straight rim. No flip can take an
  // apex's edges to the rim's new vertices away (they would make flat faces), so every split along
  // the rim raises the apex's valence: 33,000 after the first sweep, which ran into the face limit
  // (200,000), every ring walk after it as long. The clock was read only between iterations, and
  // the taken-back record counted the crossings of the 200,000 faces: minutes past a limit of
  // seconds. The sweeps now read it every few hundred steps, and a remeshing stopped half-way is
  // not searched for crossings.
  TriMesh part = load_mesh(MESHPREP_TEST_DATA_DIR "/cone_apex_fans.off").mesh;
  const std::size_t faces = part.n_faces();
  EnhanceParams params;
  params.remesh = EnhanceRemesh::On;
  params.time_limit_seconds = 1;
  const EnhanceResult result = enhance(part, nullptr, params);
  if (result.remeshed) GTEST_SKIP() << "the remeshing finished within a second: nothing ran away";
  const auto remeshing = std::find_if(result.taken_back.begin(), result.taken_back.end(),
                                      [](const TakenBack& t) { return t.work == "remeshing"; });
  ASSERT_NE(remeshing, result.taken_back.end());
  EXPECT_EQ(remeshing->guard, "time limit");
  EXPECT_TRUE(result.stopped_by_time_limit);
  for (const GuardFigure& figure : remeshing->before) EXPECT_NE(figure.name, "self_intersections");
  EXPECT_EQ(part.n_faces(), faces);  // the input's own faces, enhanced
  EXPECT_EQ(find_self_intersections(soup_from_mesh(part)).count, 0u);
}

TEST(AdaptiveRemeshing, AClockThatRunsOutMidSweepEndsItThereWithAValidMesh) {
  // One iteration, and a clock that says "out of time" from its second question on: the first is
  // asked before the iteration, so only a question inside the sweeps can stop it.
  TriangleSoup sphere = test::icosphere(3);
  for (Vec3& p : sphere.points) p.z() *= 0.3;  // flattened: its poles' faces need splits
  Remeshing setup(sphere);
  setup.rules.iterations = 1;
  int questions = 0;
  setup.rules.out_of_time = [&] { return ++questions > 1; };
  const RemeshCounts counts = remesh_to_sizing(setup.mesh, setup.constraints, setup.sizing, setup.rules);
  EXPECT_TRUE(counts.stopped_by_time);
  EXPECT_EQ(questions, 2);  // asked no more once it said so
  const TriangleSoup remeshed = soup_from_mesh(setup.mesh);
  EXPECT_EQ(find_self_intersections(remeshed).count, 0u);
  for (const auto e : setup.mesh.edges()) EXPECT_FALSE(setup.mesh.is_boundary(e));
}
