// A stage's own output check: a non-finite coordinate is the stage's failure, named with it.
#include "meshprep/core/errors.h"
#include "meshprep/core/finite_points.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

using namespace meshprep;

TEST(FinitePoints, ANonFiniteCoordinateIsTheStagesFailureNamingTheVertex) {
  std::vector<Vec3> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_NO_THROW(require_finite_points(points, "smooth"));
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()}) {
    points[2].y() = bad;
    try {
      require_finite_points(points, "smooth");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const SolverError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind("smooth failed: vertex 2 ", 0), 0u) << message;
    }
  }
}

TEST(FinitePoints, TheHalfedgeMeshIsCheckedLikeThePoints) {
  TriMesh mesh;
  const auto a = mesh.add_vertex({0, 0, 0}), b = mesh.add_vertex({1, 0, 0}),
             c = mesh.add_vertex({0, std::numeric_limits<double>::quiet_NaN(), 0});
  mesh.add_face(a, b, c);
  EXPECT_THROW(require_finite_points(mesh, "enhance"), SolverError);
  mesh.set_point(c, {0, 1, 0});
  EXPECT_NO_THROW(require_finite_points(mesh, "enhance"));
}
