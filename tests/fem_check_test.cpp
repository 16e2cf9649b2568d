#include "meshprep/core/errors.h"
#include "meshprep/fem/fem_check.h"
#include "tet_test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace meshprep;

namespace {

// The patch test solves K u = b whose exact solution is the linear field's nodal values. CG stops
// at a relative residual of 1e-14, so the relative nodal error is at most cond(K) 1e-14, with
// cond(K) = O(h^-2) <= ~1e3 on these meshes: <= 1e-11 (measured 1e-16 to 2e-14). Any assembly or
// boundary mistake gives an O(1) error.
constexpr double kPatchTolerance = 1e-10;

// cube_tets(n) with every interior node moved by up to +-0.1 h per coordinate (mt19937 is the same
// on every platform): breaks the uniform mesh's symmetry, on which P1 is nodally exact for u.
TetMesh jittered_cube(int n) {
  TetMesh m = test::cube_tets(n);
  std::mt19937 random(42);
  const double h = 1.0 / n;
  auto offset = [&] { return 0.2 * h * (double(random()) / double(std::mt19937::max()) - 0.5); };
  for (auto& p : m.points) {
    const bool interior = (p.array() > 0.5 * h).all() && (p.array() < 1.0 - 0.5 * h).all();
    if (interior) p += Vec3(offset(), offset(), offset());
  }
  return m;
}

}  // namespace

TEST(FemCheck, PatchTestIsExact) {
  const int n = 3;
  const FemCheckResult r = run_fem_check(test::cube_tets(n));
  EXPECT_LE(r.patch_test_max_error, kPatchTolerance);
  EXPECT_EQ(r.unknowns, std::size_t((n - 1) * (n - 1) * (n - 1)));  // the interior lattice nodes
  EXPECT_NEAR(r.h_max, std::sqrt(3.0) / n, 1e-15);  // every tet holds its cell's diagonal
  EXPECT_TRUE(r.solver_converged);
}

TEST(FemCheck, ExactNormOfTheSolution) {
  // ||u||^2 over the unit cube = int (x^2 + y^2 + z^2)^2 = 3/5 + 6/9 = 19/15: the quadrature is
  // exact for this degree-4 integrand, so only round-off separates the two.
  const FemCheckResult r = run_fem_check(test::cube_tets(2));
  EXPECT_NEAR(r.poisson_l2_error / r.poisson_l2_relative, std::sqrt(19.0 / 15.0), 1e-13);
}

TEST(FemCheck, PoissonIsSecondOrderInL2) {
  // P1 elements: ||u_h - u||_L2 = O(h^2), so halving h divides the error by ~4 (the leading term
  // of the error expansion dominates already at n = 4 on this smooth problem).
  double previous = 0;
  for (const int n : {4, 8, 16}) {
    const FemCheckResult r = run_fem_check(test::cube_tets(n));
    EXPECT_LE(r.patch_test_max_error, kPatchTolerance) << "n = " << n;
    if (previous > 0) {
      const double ratio = previous / r.poisson_l2_error;
      EXPECT_GT(ratio, 3.5) << "n = " << n;
      EXPECT_LT(ratio, 4.5) << "n = " << n;
    }
    previous = r.poisson_l2_error;
  }
}

TEST(FemCheck, PoissonIsSecondOrderOnAnIrregularMesh) {
  // On the uniform mesh u_h equals u at the nodes, so the error is the interpolation error, exactly
  // h^2-proportional (ratio 4.000); the jittered meshes test the solve itself. Each level has its
  // own jitter, so the error constant varies a little between levels (ratios measured 3.96 to
  // 4.00 over four seeds and n = 4 to 32): 4 +- 0.5 leaves a wide margin.
  const FemCheckResult coarse = run_fem_check(jittered_cube(8));
  const FemCheckResult fine = run_fem_check(jittered_cube(16));
  EXPECT_LE(coarse.patch_test_max_error, kPatchTolerance);
  EXPECT_LE(fine.patch_test_max_error, kPatchTolerance);
  const double ratio = coarse.poisson_l2_error / fine.poisson_l2_error;
  EXPECT_GT(ratio, 3.5);
  EXPECT_LT(ratio, 4.5);
}

TEST(FemCheck, BoundaryDerivedFromTetsWhenNoFacesGiven) {
  const TetMesh with_faces = test::cube_tets(3);
  TetMesh without_faces = with_faces;
  without_faces.boundary_faces.clear();
  without_faces.boundary_tags.clear();
  const FemCheckResult a = run_fem_check(with_faces);
  const FemCheckResult b = run_fem_check(without_faces);
  EXPECT_EQ(b.unknowns, a.unknowns);
  EXPECT_LE(b.patch_test_max_error, kPatchTolerance);
  EXPECT_DOUBLE_EQ(b.poisson_l2_error, a.poisson_l2_error);
}

TEST(FemCheck, PointsOutsideTheTetsAreIgnored) {
  TetMesh m = test::cube_tets(2);
  m.points.push_back({5, 5, 5});  // used by no tet: neither an unknown nor part of the error
  const FemCheckResult r = run_fem_check(m);
  EXPECT_EQ(r.unknowns, 1u);
  EXPECT_LE(r.patch_test_max_error, kPatchTolerance);
}

TEST(FemCheck, NoInteriorNode) {
  // n = 1: every node is on the boundary, nothing to solve; the error is the interpolation error.
  const FemCheckResult r = run_fem_check(test::cube_tets(1));
  EXPECT_EQ(r.unknowns, 0u);
  EXPECT_EQ(r.patch_test_max_error, 0.0);
  EXPECT_GT(r.poisson_l2_error, 0.0);
  EXPECT_TRUE(r.solver_converged);
}

TEST(FemCheck, RejectsInvalidMeshes) {
  EXPECT_THROW(run_fem_check(TetMesh{}), InvalidInput);
  TetMesh inverted = test::cube_tets(2);
  std::swap(inverted.tets[7][0], inverted.tets[7][1]);
  EXPECT_THROW(run_fem_check(inverted), InvalidInput);
  TetMesh flat = test::cube_tets(2);
  flat.points[flat.tets[0][3]] = flat.points[flat.tets[0][0]];
  EXPECT_THROW(run_fem_check(flat), InvalidInput);
  TetMesh dangling = test::cube_tets(2);
  dangling.tets[0][2] = 1000;
  EXPECT_THROW(run_fem_check(dangling), InvalidInput);
}

TEST(FemCheck, JsonKeys) {
  const nlohmann::ordered_json j = to_json(run_fem_check(test::cube_tets(2)));
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  const std::vector<std::string> expected{"patch_test_max_error", "poisson_l2_error", "poisson_l2_relative",
                                          "h_max", "unknowns", "solver_converged"};
  EXPECT_EQ(keys, expected);
  EXPECT_EQ(j["unknowns"], 1);
  EXPECT_EQ(j["solver_converged"], true);
}
