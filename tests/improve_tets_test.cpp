// Tet improvement (fem/include/meshprep/fem/improve_tets.h and its pieces in fem/src/improve/):
// the objective, the mesh's bookkeeping, each move alone (volume, boundary and orientation kept
// exactly), the whole schedule on TetGen's tets, regions, what the surface forbids, and stopping.
#include "improve/compound_move.h"
#include "improve/edge_contraction.h"
#include "improve/exact_orientation.h"
#include "improve/surface_limits.h"
#include "improve/tet_complex.h"
#include "improve/tet_objective.h"
#include "improve/topological_moves.h"
#include "improve/vertex_insertion.h"
#include "improve/vertex_smoothing.h"

#include "meshprep/core/errors.h"
#include "meshprep/fem/export.h"
#include "meshprep/fem/improve_tets.h"
#include "meshprep/fem/tet_boundary.h"
#include "meshprep/fem/tet_quality.h"
#include "meshprep/fem/tetrahedralize.h"
#include "meshprep/quality/triangle_bvh.h"

#include "scratch_dir.h"
#include "tet_test_meshes.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

using namespace meshprep;
using namespace meshprep::improve;

namespace {

constexpr double kDegree = M_PI / 180.0;
// The weight of 15 and 160 degrees (ImproveParams' defaults).
const double kWeight = std::sin(15 * kDegree) / std::sin(20 * kDegree);

double total_volume(const TetMesh& m) {
  double v = 0;
  for (std::size_t t = 0; t < m.tets.size(); ++t) v += tet_volume(m, t);
  return v;
}

// Every tet positive, by the plain floating-point volume (independent of the exact predicate the
// improvement relies on; a real inversion is far from round-off).
bool all_positive(const TetMesh& m) {
  for (std::size_t t = 0; t < m.tets.size(); ++t)
    if (!(tet_volume(m, t) > 0)) return false;
  return true;
}

// The faces with one tet (or, with `interfaces`, between two regions), each as the coordinates of
// its corners, oriented out of its tet and rotated to start at its smallest corner: equal lists
// mean the same boundary, bit for bit, whatever the numbering.
using FaceGeometry = std::array<double, 9>;
std::vector<FaceGeometry> faces_of(const TetMesh& m, bool interfaces) {
  std::map<std::array<std::uint32_t, 3>, std::vector<std::pair<std::size_t, int>>> faces;
  for (std::size_t t = 0; t < m.tets.size(); ++t)
    for (int c = 0; c < 4; ++c) {
      auto f = outward_face(m.tets[t], c);
      std::sort(f.begin(), f.end());
      faces[f].push_back({t, c});
    }
  std::vector<FaceGeometry> out;
  for (const auto& [key, owners] : faces) {
    const bool wanted = interfaces ? owners.size() == 2 && m.tet_regions[owners[0].first] != m.tet_regions[owners[1].first]
                                   : owners.size() == 1;
    if (!wanted) continue;
    for (const auto& [t, c] : owners) {
      std::array<Vec3, 3> p;
      const auto f = outward_face(m.tets[t], c);
      for (int k = 0; k < 3; ++k) p[k] = m.points[f[k]];
      const auto less = [](const Vec3& a, const Vec3& b) { return std::tie(a.x(), a.y(), a.z()) < std::tie(b.x(), b.y(), b.z()); };
      const int first = static_cast<int>(std::min_element(p.begin(), p.end(), less) - p.begin());
      FaceGeometry g;
      for (int k = 0; k < 3; ++k)
        for (int d = 0; d < 3; ++d) g[3 * k + d] = p[(first + k) % 3][d];
      out.push_back(g);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// cube_tets(n) with its inner points moved at random by up to `jitter` cells, each move kept only
// if every tet stays positive: a valid mesh with many bad tets. One region unless `regions`.
TetMesh jittered_cube(int n, double jitter, unsigned seed, bool regions = false) {
  TetMesh m = test::cube_tets(n);
  if (!regions) std::fill(m.tet_regions.begin(), m.tet_regions.end(), 1);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-jitter / n, jitter / n);
  for (Vec3& p : m.points) {
    const bool inner = p.minCoeff() > 1e-9 && p.maxCoeff() < 1 - 1e-9;
    const bool interface = regions && std::abs(p.x() - 0.5) < 1e-9;
    if (!inner || interface) continue;
    const Vec3 before = p;
    p += Vec3(offset(random), offset(random), offset(random));
    if (!all_positive(m)) p = before;
  }
  return m;
}

double worst_quality(const TetComplex& c) {
  double w = 1;
  for (TetId t = 0; t < c.tet_slots(); ++t)
    if (c.alive(t)) w = std::min(w, c.quality(t));
  return w;
}

// The six dihedral angles of a tet, from the angle between outward normals (independent of the
// objective's sine formula).
std::array<double, 6> dihedral_angles(const std::array<Vec3, 4>& p) {
  const Tetrahedron t{0, 1, 2, 3};
  std::array<Vec3, 4> n;
  for (int c = 0; c < 4; ++c) {
    const auto f = outward_face(t, c);
    n[c] = (p[f[1]] - p[f[0]]).cross(p[f[2]] - p[f[0]]);
  }
  std::array<double, 6> angles;
  int k = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) angles[k++] = M_PI - std::atan2(n[a].cross(n[b]).norm(), n[a].dot(n[b]));
  return angles;
}

std::array<Vec3, 4> random_positive_tet(std::mt19937& random) {
  std::uniform_real_distribution<double> u(-1, 1);
  while (true) {
    std::array<Vec3, 4> p;
    for (Vec3& q : p) q = Vec3(u(random), u(random), u(random));
    if ((p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])) > 1e-3) return p;
  }
}

}  // namespace

TEST(TetObjective, RegularTetScoresTheSineOfItsDihedralAngle) {
  const Vec3 p0(1, 1, 1), p1(1, -1, -1), p2(-1, 1, -1), p3(-1, -1, 1);
  const double regular = std::sqrt(8.0 / 9.0);  // sin(acos(1/3))
  EXPECT_NEAR(biased_min_sine(p0, p2, p1, p3, kWeight), regular, 1e-15);
  // Scale-free and invariant under rigid motion.
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  for (const double s : {1e-3, 1e3}) {
    // Far from the origin the coordinates' differences lose |t| / s ulps of the tet's size.
    const Vec3 t(5e2, -3, 7);
    const double tolerance = 1e-14 * (1 + t.norm() / s);
    EXPECT_NEAR(biased_min_sine(s * r * p0 + t, s * r * p2 + t, s * r * p1 + t, s * r * p3 + t, kWeight), regular,
                tolerance);
  }
  // Inverted: negative; flat: zero.
  EXPECT_LT(biased_min_sine(p0, p1, p2, p3, kWeight), 0);
  EXPECT_EQ(biased_min_sine(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), kWeight), 0);
}

TEST(TetObjective, IsTheSmallestSineWithObtuseAnglesWeighted) {
  std::mt19937 random(7);
  for (int trial = 0; trial < 200; ++trial) {
    const auto p = random_positive_tet(random);
    double expected = 1;
    for (const double a : dihedral_angles(p)) expected = std::min(expected, (a > M_PI / 2 ? kWeight : 1.0) * std::sin(a));
    EXPECT_NEAR(biased_min_sine(p[0], p[1], p[2], p[3], kWeight), expected, 1e-12) << "trial " << trial;
  }
}

TEST(TetObjective, GradientMatchesFiniteDifferences) {
  std::mt19937 random(11);
  int checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    auto p = random_positive_tet(random);
    if (trial % 4 == 0) std::swap(p[0], p[1]), std::swap(p[2], p[3]);  // an even permutation
    const ObjectiveWithGradient g = biased_min_sine_gradient(p[0], p[1], p[2], p[3], kWeight);
    EXPECT_NEAR(g.value, biased_min_sine(p[0], p[1], p[2], p[3], kWeight), 1e-15);
    // Central differences, step h: error O(h^2) where the smallest term is smooth; skipped
    // where two terms are within the step's reach of each other (a kink).
    const double h = 1e-6;
    bool smooth = true;
    Vec3 numeric;
    for (int d = 0; d < 3; ++d) {
      Vec3 a = p[3], b = p[3];
      a[d] += h, b[d] -= h;
      const double fa = biased_min_sine(p[0], p[1], p[2], a, kWeight), fb = biased_min_sine(p[0], p[1], p[2], b, kWeight);
      numeric[d] = (fa - fb) / (2 * h);
      const double fm = g.value, curvature = std::abs(fa + fb - 2 * fm) / (h * h);
      smooth = smooth && curvature < 1e3;
    }
    if (!smooth) continue;
    ++checked;
    EXPECT_NEAR((g.gradient - numeric).norm(), 0, 1e-6 * std::max(1.0, numeric.norm())) << "trial " << trial;
  }
  EXPECT_GT(checked, 150);
}

TEST(TetComplex, KnowsNeighboursConstraintsAndFreeVertices) {
  const TetMesh m = test::cube_tets(4);  // regions split at x = 0.5
  const TetComplex c(m, kWeight);
  std::size_t constrained = 0, boundary = 0;
  for (TetId t = 0; t < c.tet_slots(); ++t)
    for (int k = 0; k < 4; ++k) {
      constrained += c.constrained(t, k);
      boundary += c.neighbour(t, k) == kNoTet;
      const TetId n = c.neighbour(t, k);
      if (n == kNoTet) continue;
      // Neighbours are mutual.
      int back = 0;
      for (int j = 0; j < 4; ++j) back += c.neighbour(n, j) == t;
      EXPECT_EQ(back, 1);
    }
  EXPECT_EQ(boundary, 6u * 16 * 2);
  EXPECT_EQ(constrained, boundary + 2 * 16 * 2);  // and both sides of the 32 interface faces
  std::size_t free = 0;
  for (VertexId v = 0; v < c.points(); ++v) free += c.free_vertex(v);
  EXPECT_EQ(free, 27u - 9u);  // inner points off the interface plane
}

TEST(TetComplex, RefusesAFaceOfThreeTetsAndOverlappingTets) {
  TetMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {0.2, 0.2, 2}};
  m.tets = {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 5}};
  m.tet_regions = {1, 1, 1};
  EXPECT_THROW(TetComplex(m, kWeight), InvalidInput);
  m.tets = {{0, 1, 2, 3}, {0, 1, 2, 5}};  // both on the same side of face 012
  m.tet_regions = {1, 1};
  EXPECT_THROW(TetComplex(m, kWeight), InvalidInput);
}

TEST(TetComplex, ReplaceAcceptsOnlyARetriangulationOfTheSameSpace) {
  // Two tets on the face (0, 1, 2), apexes 3 above and 4 below: the 2-3 flip to the three tets
  // around the edge 3-4 is valid; variants that invert, leave a gap, overlap or drop a vertex are not.
  TetMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 1}, {0.3, 0.3, -1}};
  m.tets = {{0, 1, 2, 3}, {0, 2, 1, 4}};
  m.tet_regions = {1, 1};
  const std::vector<Tetrahedron> flip = {{0, 1, 4, 3}, {1, 2, 4, 3}, {2, 0, 4, 3}};
  for (const Tetrahedron& t : flip) {
    TetMesh one = m;
    one.tets = {t};
    ASSERT_GT(tet_volume(one, 0), 0);
  }
  const std::vector<std::vector<Tetrahedron>> invalid = {
      {{0, 1, 3, 4}, {1, 2, 4, 3}, {2, 0, 4, 3}},  // one inverted
      {{0, 1, 4, 3}, {1, 2, 4, 3}},                // a gap
      {{0, 1, 4, 3}, {1, 2, 4, 3}, {2, 0, 4, 3}, {0, 1, 2, 3}},  // an overlap
      {{0, 1, 2, 3}, {0, 1, 2, 3}}};               // a tet twice
  TetComplex c(m, kWeight);
  for (const auto& fresh : invalid) {
    EXPECT_FALSE(c.replace({0, 1}, fresh));
    EXPECT_TRUE(c.alive(0) && c.alive(1));
    EXPECT_EQ(c.tet(0), m.tets[0]);
  }
  // The same flip where the edge 3-4 misses the triangle: faces match, but one tet is inverted
  // (only the exact orientation test tells).
  TetMesh skew = m;
  skew.points[3] = {0.8, 0.8, 1};
  skew.points[4] = {0.8, 0.8, -1};
  TetComplex s(skew, kWeight);
  EXPECT_FALSE(s.replace({0, 1}, flip));
  ASSERT_TRUE(c.replace({0, 1}, flip));
  const TetMesh after = c.to_mesh(m);
  EXPECT_EQ(after.tets.size(), 3u);
  EXPECT_NEAR(total_volume(after), total_volume(m), 1e-15);
  EXPECT_EQ(faces_of(after, false), faces_of(m, false));
  // Undo with the old ids: the mesh is as before, ids included.
  const std::vector<TetId> created = c.created();
  const std::vector<TetId> old_ids = {0, 1};
  ASSERT_TRUE(c.replace(created, m.tets, &old_ids));
  EXPECT_EQ(c.live_tets(), 2u);
  EXPECT_EQ(c.tet(0), m.tets[0]);
  EXPECT_EQ(c.tet(1), m.tets[1]);
}

namespace {

enum class MoveKind { EdgeRemoval, MultiFaceRemoval, Smoothing, Contraction, Compound, Insertion };
const char* name_of(MoveKind k) {
  switch (k) {
    case MoveKind::EdgeRemoval: return "EdgeRemoval";
    case MoveKind::MultiFaceRemoval: return "MultiFaceRemoval";
    case MoveKind::Smoothing: return "Smoothing";
    case MoveKind::Contraction: return "Contraction";
    case MoveKind::Compound: return "Compound";
    default: return "Insertion";
  }
}

// One sweep of a single kind of move over every tet, worst first; the moves applied.
std::size_t sweep(TetComplex& c, MoveKind kind) {
  std::vector<TetId> order;
  for (TetId t = 0; t < c.tet_slots(); ++t) order.push_back(t);
  std::sort(order.begin(), order.end(), [&](TetId a, TetId b) { return c.quality(a) < c.quality(b); });
  std::size_t applied = 0;
  std::vector<TetId> changed;
  for (const TetId t : order) {
    if (!c.alive(t)) continue;
    const Tetrahedron tet = c.tet(t);
    bool done = false;
    switch (kind) {
      case MoveKind::EdgeRemoval:
      case MoveKind::Compound:
        for (int i = 0; i < 4 && !done; ++i)
          for (int j = i + 1; j < 4 && !done; ++j) {
            const Move m = edge_removal(c, t, tet[i], tet[j], 10);
            if (kind == MoveKind::EdgeRemoval) done = m.improves() && c.replace(m.old, m.fresh);
            else done = !m.fresh.empty() && !m.improves() && move_and_smooth(c, m, changed);
          }
        break;
      case MoveKind::MultiFaceRemoval:
        for (int k = 0; k < 4 && !done; ++k) {
          const Move m = multi_face_removal(c, t, k, 12);
          done = m.improves() && c.replace(m.old, m.fresh);
        }
        break;
      case MoveKind::Smoothing:
        for (const VertexId v : tet) done = (c.free_vertex(v) && smooth_vertex(c, v)) || done;
        break;
      case MoveKind::Contraction:
        for (const VertexId v : tet) {
          if (done || !c.free_vertex(v)) continue;
          const Move m = best_contraction(c, v);
          done = m.improves() && c.remove_vertex(v, m.old, m.fresh);
        }
        break;
      case MoveKind::Insertion:
        done = insert_vertex(c, t, 24);
        break;
    }
    applied += done;
  }
  return applied;
}

class EachMove : public ::testing::TestWithParam<MoveKind> {};

}  // namespace

TEST_P(EachMove, KeepsVolumeBoundaryAndOrientationExactly) {
  const TetMesh before = jittered_cube(4, 0.45, 3);
  ASSERT_TRUE(all_positive(before));
  TetComplex c(before, kWeight);
  const double worst_before = worst_quality(c);
  const std::size_t applied = sweep(c, GetParam());
  EXPECT_GT(applied, 0u) << "the jittered cube has bad tets every move can raise";
  const TetMesh after = c.to_mesh(before);
  EXPECT_TRUE(all_positive(after));
  // Each move replaces tets by tets filling the same space: the sums differ by round-off only.
  EXPECT_NEAR(total_volume(after), total_volume(before), 1e-14);
  EXPECT_EQ(faces_of(after, false), faces_of(before, false));
  EXPECT_GE(worst_quality(c), worst_before);
  EXPECT_NO_THROW(TetComplex(after, kWeight));  // no face of three tets, no overlap
}

INSTANTIATE_TEST_SUITE_P(Moves, EachMove,
                         ::testing::Values(MoveKind::EdgeRemoval, MoveKind::MultiFaceRemoval, MoveKind::Smoothing,
                                           MoveKind::Contraction, MoveKind::Compound, MoveKind::Insertion),
                         [](const auto& param_info) { return std::string(name_of(param_info.param)); });

TEST(Smoothing, NeverInvertsATetUnderRandomPerturbations) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const TetMesh m = jittered_cube(3, 0.49, seed);
    TetComplex c(m, kWeight);
    std::vector<TetId> star;
    for (int round = 0; round < 3; ++round)
      for (VertexId v = 0; v < c.points(); ++v) {
        if (!c.free_vertex(v)) continue;
        c.star(v, star);
        double worst = 1;
        for (const TetId t : star) worst = std::min(worst, c.quality(t));
        smooth_vertex(c, v);
        double now = 1;
        for (const TetId t : star) {
          now = std::min(now, c.quality(t));
          const Tetrahedron& k = c.tet(t);
          EXPECT_TRUE(positively_oriented(c.point(k[0]), c.point(k[1]), c.point(k[2]), c.point(k[3]))) << "seed " << seed;
        }
        EXPECT_GE(now, worst) << "seed " << seed;
      }
    EXPECT_TRUE(all_positive(c.to_mesh(m))) << "seed " << seed;
  }
}

TEST(ImproveTets, RemovesASliverBetweenFourSurfaceVertices) {
  // A bipyramid over a square whose corners go up and down by 2 % of its side: the sliver of the
  // four corners (no face on the surface), the two tets above its upper diagonal and the two
  // below its lower one. All six points are on the surface; only flips can help.
  TetMesh m;
  const double d = 0.02;
  m.points = {{0, 0, d}, {1, 0, -d}, {1, 1, d}, {0, 1, -d}, {0.5, 0.5, 1}, {0.5, 0.5, -1}};
  m.tets = {{0, 1, 2, 3}, {4, 0, 1, 2}, {4, 0, 2, 3}, {5, 1, 2, 3}, {5, 1, 3, 0}};
  m.tet_regions.assign(m.tets.size(), 1);
  for (std::size_t t = 0; t < m.tets.size(); ++t)
    if (tet_volume(m, t) < 0) std::swap(m.tets[t][2], m.tets[t][3]);
  ASSERT_TRUE(all_positive(m));
  const TetQualityReport before = analyze_tet_quality(m);
  ASSERT_LT(before.min_dihedral_deg.min, 5);
  const auto boundary = faces_of(m, false);
  const double volume = total_volume(m);
  const ImproveResult r = improve_tets(m);
  EXPECT_EQ(faces_of(m, false), boundary);
  EXPECT_NEAR(total_volume(m), volume, 1e-15);
  EXPECT_TRUE(all_positive(m));
  EXPECT_GT(r.min_dihedral_after_deg, 15);
  EXPECT_EQ(r.stopped_by, "goal reached");
  EXPECT_EQ(analyze_tet_quality(m).min_dihedral_deg.min, r.min_dihedral_after_deg);
}

// A pyramid whose square base is triangulated on the boundary by one diagonal (b, d) and inside
// by the other (a, c): between them a tet of the four base corners, flat when the base is planar
// (what TetGen leaves where a CAD face is planar only to rounding). `rotation` and `scale` place the
// part so that the base is planar only to rounding (a part rotated, in metres). Base faces are
// tagged 1, the sides 2.
TetMesh pyramid_with_flat_base_tet(const Eigen::Matrix3d& rotation, double scale) {
  TetMesh m;
  // a, b, c, d, the apex e below the base.
  const std::vector<Vec3> at = {{0, 0, 0}, {1, 0, 0}, {1.1, 1, 0}, {0, 1, 0}, {0.5, 0.5, -0.8}};
  // The orientations are those of the base with b and d raised (a ridge along the boundary's
  // diagonal), whose limit the flat tet is.
  std::vector<Vec3> ridge = at;
  ridge[1].z() = ridge[3].z() = 0.01;
  for (const Vec3& p : at) m.points.push_back(scale * (rotation * p));
  m.tets = {{0, 1, 2, 3}, {0, 1, 2, 4}, {0, 2, 3, 4}};
  m.tet_regions.assign(3, 1);
  for (auto& t : m.tets) {
    const double v = (ridge[t[1]] - ridge[t[0]]).dot((ridge[t[2]] - ridge[t[0]]).cross(ridge[t[3]] - ridge[t[0]]));
    if (v < 0) std::swap(t[2], t[3]);
  }
  const auto outward = [&](std::array<std::uint32_t, 3> f) {  // away from the solid's inside
    const Vec3 inside = (ridge[0] + ridge[2] + ridge[4]) / 3;
    if ((ridge[f[1]] - ridge[f[0]]).cross(ridge[f[2]] - ridge[f[0]]).dot(ridge[f[0]] - inside) < 0) std::swap(f[1], f[2]);
    return f;
  };
  m.boundary_faces = {outward({0, 1, 3}), outward({1, 2, 3}), outward({0, 1, 4}), outward({1, 2, 4}),
                      outward({2, 3, 4}), outward({3, 0, 4})};
  m.boundary_tags = {1, 1, 2, 2, 2, 2};
  return m;
}

class FlatBoundaryTet : public test::ScratchDirTest {};

TEST_F(FlatBoundaryTet, IsRemovedByFlippingTheBoundaryAndNeverWritten) {
  const Eigen::Matrix3d turned = (Eigen::AngleAxisd(0.37, Vec3(0.3, 1, 0.2).normalized()) *
                                  Eigen::AngleAxisd(0.61, Vec3::UnitX())).toRotationMatrix();
  for (const auto& [rotation, scale] : {std::pair(Eigen::Matrix3d(Eigen::Matrix3d::Identity()), 1.0),
                                        std::pair(turned, 1e-3), std::pair(turned, 1e3)}) {
    TetMesh m = pyramid_with_flat_base_tet(rotation, scale);
    ASSERT_EQ(flat_tets(m), std::vector<std::size_t>{0}) << scale;
    // No writer takes it.
    const std::string file = path("flat" + std::to_string(scale) + ".msh");
    EXPECT_THROW(write_tet_mesh(m, file), InvalidInput);
    EXPECT_FALSE(std::filesystem::exists(file));
    const double volume = total_volume(m);
    const ImproveResult r = improve_tets(m);
    EXPECT_EQ(r.flat_boundary_tets_removed, 1u) << scale;
    EXPECT_TRUE(flat_tets(m).empty()) << scale;
    EXPECT_EQ(m.tets.size(), 2u);
    // The flat tet's volume was zero to rounding: the solid's is the same to rounding.
    EXPECT_NEAR(total_volume(m), volume, 1e-14 * std::pow(scale, 3)) << scale;
    // The base is triangulated by the other diagonal (a, c) now, with its tag; the sides as they were.
    std::map<std::array<std::uint32_t, 3>, int> tags;
    for (std::size_t f = 0; f < m.boundary_faces.size(); ++f) {
      auto key = m.boundary_faces[f];
      std::sort(key.begin(), key.end());
      tags[key] = m.boundary_tags[f];
    }
    EXPECT_EQ(tags, (std::map<std::array<std::uint32_t, 3>, int>{
                        {{0, 1, 2}, 1}, {{0, 2, 3}, 1}, {{0, 1, 4}, 2}, {{1, 2, 4}, 2}, {{2, 3, 4}, 2}, {{0, 3, 4}, 2}}));
    // Each listed face is outward: a face of one tet, oriented as that tet's outward face.
    std::vector<std::array<std::uint32_t, 3>> outward;
    for (const Tetrahedron& t : m.tets)
      for (int c = 0; c < 4; ++c) outward.push_back(outward_face(t, c));
    for (const auto& f : m.boundary_faces) {
      const bool found = std::any_of(outward.begin(), outward.end(), [&](const std::array<std::uint32_t, 3>& g) {
        for (int k = 0; k < 3; ++k)
          if (g[k] == f[0] && g[(k + 1) % 3] == f[1] && g[(k + 2) % 3] == f[2]) return true;
        return false;
      });
      EXPECT_TRUE(found) << f[0] << " " << f[1] << " " << f[2];
    }
    EXPECT_NO_THROW(write_tet_mesh(m, file));
  }
}

TEST(ImproveTets, LeavesAnInvertedTetOnTheBoundaryToTheTangleCheck) {
  // The same tet made clearly inverted (the base's far corner pushed through): a tangle, not a
  // plane: the improvement refuses the mesh rather than remove it.
  TetMesh m = pyramid_with_flat_base_tet(Eigen::Matrix3d::Identity(), 1);
  m.points[2].z() = 0.3;
  EXPECT_THROW(improve_tets(m), InvalidInput);
}

TEST(ImproveTets, TetGensTetsOfASphereReachTheGoalAtAnyScale) {
  for (const double scale : {1e-3, 1.0, 1e3}) {
    TriangleSoup sphere = test::icosphere(3, scale);
    TetParams params;
    params.keep_surface = true;
    TetMesh tets = tetrahedralize_plc(plc_from_surface(sphere), params);
    const auto boundary = faces_of(tets, false);
    const double volume = total_volume(tets);
    const ImproveResult r = improve_tets(tets);
    EXPECT_LT(r.min_dihedral_before_deg, 15) << scale;  // TetGen's slivers
    EXPECT_EQ(r.stopped_by, "goal reached") << scale;
    EXPECT_GE(r.min_dihedral_after_deg, 15) << scale;
    EXPECT_LE(r.max_dihedral_after_deg, 160) << scale;
    EXPECT_EQ(r.below_goal_after, 0u) << scale;
    EXPECT_EQ(faces_of(tets, false), boundary) << scale;
    EXPECT_NEAR(total_volume(tets), volume, 1e-12 * volume) << scale;
    EXPECT_TRUE(all_positive(tets)) << scale;
    EXPECT_EQ(r.limiting_edge_count, 0u) << scale;
  }
}

TEST(ImproveTets, KeepsRegionsInterfacesAndTags) {
  TetMesh m = jittered_cube(4, 0.45, 5, /*regions=*/true);
  const auto boundary = faces_of(m, false), interfaces = faces_of(m, true);
  const std::vector<Triangle> tagged = m.boundary_faces;
  const std::vector<int> tags = m.boundary_tags;
  std::map<int, double> volume;
  for (std::size_t t = 0; t < m.tets.size(); ++t) volume[m.tet_regions[t]] += tet_volume(m, t);
  const ImproveResult r = improve_tets(m);
  EXPECT_GT(r.min_dihedral_after_deg, r.min_dihedral_before_deg);
  EXPECT_EQ(faces_of(m, false), boundary);
  EXPECT_EQ(faces_of(m, true), interfaces);
  std::map<int, double> after;
  for (std::size_t t = 0; t < m.tets.size(); ++t) after[m.tet_regions[t]] += tet_volume(m, t);
  ASSERT_EQ(after.size(), 2u);
  for (const auto& [region, v] : volume) EXPECT_NEAR(after[region], v, 1e-14) << region;
  // No point of a constrained face moved or was renumbered: the tagged faces still name them.
  EXPECT_EQ(m.boundary_faces, tagged);
  EXPECT_EQ(m.boundary_tags, tags);
}

TEST(ImproveTets, NamesTheEdgesWhereTheSurfaceForbidsTheGoal) {
  // A prism over a triangle with a 10-degree corner: its edge there is sharper than any goal.
  const double a = 10 * kDegree;
  TriangleSoup prism;
  prism.points = {{0, 0, 0}, {1, 0, 0}, {std::cos(a), std::sin(a), 0}, {0, 0, 1}, {1, 0, 1}, {std::cos(a), std::sin(a), 1}};
  prism.triangles = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {2, 0, 3}, {2, 3, 5}};
  TetParams params;
  params.keep_surface = false;
  TetMesh tets = tetrahedralize_plc(plc_from_surface(prism), params);
  const ImproveResult r = improve_tets(tets);
  ASSERT_GE(r.limiting_edge_count, 1u);
  EXPECT_NEAR(r.limiting_edges.front().interior_angle_deg, 10, 1e-9);
  EXPECT_LE(r.surface_bound_deg, 10 + 1e-9);
  EXPECT_NEAR(r.limiting_edges.front().midpoint.x(), 0, 1e-12);  // on the edge x = y = 0
  EXPECT_NEAR(r.limiting_edges.front().midpoint.y(), 0, 1e-12);
  EXPECT_LE(r.min_dihedral_after_deg, r.surface_bound_deg + 1e-9);  // the bound holds
}

TEST(SurfaceLimits, AWedgeFilledByTwoTetsIsBoundedByItsBestSplit) {
  // A 28-degree wedge at the edge u-v whose boundary faces are needles reaching far past v: the one
  // tet joining both faces' far corners is flat, and three or more tets at the edge leave one at
  // most 28 / 3 degrees there, so the bound is decided by the best inner point X of the two tets
  // (face 1, X), (face 2, X). Two tets split the 28 degrees at the edge: the bound is at most 14,
  // under the goal of 15.
  const double alpha = 28 * kDegree;
  TetMesh m;
  m.points = {{0, 0, 0}, {0, 0, 1}, {0.2, 0, 3}, {0.2 * std::cos(alpha), 0.2 * std::sin(alpha), 3},
              {0.1 * std::cos(alpha / 2), 0.1 * std::sin(alpha / 2), 1.5}};
  m.tets = {{0, 1, 2, 4}, {0, 1, 4, 3}};
  m.tet_regions = {1, 1};
  if (!all_positive(m)) std::swap(m.tets[0][0], m.tets[0][1]), std::swap(m.tets[1][0], m.tets[1][1]);
  ASSERT_TRUE(all_positive(m));
  const TetComplex c(m, kWeight);
  const double forced = tet_shape(m.points[0], m.points[1], m.points[2], m.points[3]).min_dihedral_deg;
  const double given = std::min(tet_shape(m.points[0], m.points[1], m.points[2], m.points[4]).min_dihedral_deg,
                                tet_shape(m.points[0], m.points[1], m.points[4], m.points[3]).min_dihedral_deg);
  const auto limiting = limiting_boundary_edges(c, 15);
  const auto edge = std::find_if(limiting.begin(), limiting.end(), [](const LimitingBoundaryEdge& e) {
    return std::min(e.a, e.b) == 0 && std::max(e.a, e.b) == 1;
  });
  ASSERT_NE(edge, limiting.end());
  EXPECT_NEAR(edge->interior_angle_deg, 28, 1e-9);
  EXPECT_LT(forced, 28.0 / 3);
  EXPECT_GT(edge->bound_deg, std::max(forced, 28.0 / 3));  // the split decides
  EXPECT_GE(edge->bound_deg, given - 1e-6);  // at least the X the mesh has (here the best: 14)
  EXPECT_LE(edge->bound_deg, 14 + 1e-9);
}

TEST(ImproveTets, CancellationLeavesTheMeshUnchanged) {
  TetMesh m = jittered_cube(3, 0.45, 9);
  const TetMesh copy = m;
  ImproveParams params;
  params.cancelled = [] { return true; };
  EXPECT_THROW(improve_tets(m, params), Cancelled);
  EXPECT_EQ(m.tets, copy.tets);
  EXPECT_EQ(m.points, copy.points);
}

TEST(ImproveTets, RefusesGoalsOutOfRange) {
  TetMesh m = test::cube_tets(1);
  for (const auto& [lo, hi] : std::vector<std::pair<double, double>>{{0, 160}, {60, 160}, {15, 60}, {15, 180}}) {
    ImproveParams params;
    params.goal_min_dihedral_deg = lo;
    params.goal_max_dihedral_deg = hi;
    EXPECT_THROW(improve_tets(m, params), InvalidInput) << lo << " " << hi;
  }
}

namespace meshprep {
namespace {

// A goal past the default is climbed from the default goals' result and kept only if no worse:
// the high preset's tets are never worse than the default's, by the objective at the high goals.
TEST(ImproveTets, TheHighPresetEndsNoWorseThanTheDefault) {
  for (const unsigned seed : {3u, 7u, 11u}) {
    TetMesh at_default = jittered_cube(4, 0.45, seed), at_high = at_default;
    const ImproveResult d = improve_tets(at_default);
    ImproveParams high;
    apply_tet_quality(high, "high");
    EXPECT_EQ(high.goal_min_dihedral_deg, 20);
    EXPECT_EQ(high.goal_max_dihedral_deg, 150);
    EXPECT_EQ(tet_quality_of(high), "high");
    const ImproveResult h = improve_tets(at_high, high);
    const auto worst = [](double lo, double hi) {
      const double w = std::sin(20 * M_PI / 180) / std::sin(30 * M_PI / 180);
      return std::min(std::sin(lo * M_PI / 180), w * std::sin((180 - hi) * M_PI / 180));
    };
    EXPECT_GE(worst(h.min_dihedral_after_deg, h.max_dihedral_after_deg),
              worst(d.min_dihedral_after_deg, d.max_dihedral_after_deg) - 1e-12)
        << seed << ": " << h.min_dihedral_after_deg << "/" << h.max_dihedral_after_deg << " against "
        << d.min_dihedral_after_deg << "/" << d.max_dihedral_after_deg;
    EXPECT_EQ(h.min_dihedral_before_deg, d.min_dihedral_before_deg) << seed;  // both from the same tets
    EXPECT_TRUE(all_positive(at_high)) << seed;
    // The figures describe the tets returned.
    EXPECT_NEAR(analyze_tet_quality(at_high).min_dihedral_deg.min, h.min_dihedral_after_deg, 1e-9) << seed;
  }
  ImproveParams custom;
  custom.goal_min_dihedral_deg = 18;
  EXPECT_EQ(tet_quality_of(custom), "custom");
  EXPECT_THROW(apply_tet_quality(custom, "best"), InvalidInput);
}

// cube_tets(n) (one region) with every point moved at random by up to `jitter` cells within its
// place: inner points anywhere, points on a side within it, points on an edge along it, corners
// not at all; each move kept only if every tet stays positive. Its boundary is the cube's,
// exactly, with poor triangles on it.
TetMesh jittered_cube_and_boundary(int n, double jitter, unsigned seed) {
  TetMesh m = test::cube_tets(n);
  std::fill(m.tet_regions.begin(), m.tet_regions.end(), 1);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-jitter / n, jitter / n);
  for (Vec3& p : m.points) {
    const Vec3 before = p;
    for (int d = 0; d < 3; ++d)
      if (p[d] > 0 && p[d] < 1) p[d] += offset(random);
    if (!all_positive(m)) p = before;
  }
  return m;
}


TEST(BoundarySlides, KeepTheCubesSidesEdgesAndCornersWhileRaisingTheWorstTet) {
  // At the high preset's goals (20/150 deg) the jittered boundary holds the tets below 20 deg;
  // sliding on it, they reach the goal.
  for (const unsigned seed : {9u, 13u}) {
    TetMesh kept = jittered_cube_and_boundary(4, 0.45, seed), slid = kept;
    const std::vector<Vec3> first = kept.points;
    const std::vector<Triangle> first_faces = kept.boundary_faces;
    const std::vector<int> tags = kept.boundary_tags;
    ImproveParams params;
    apply_tet_quality(params, "high");
    const ImproveResult k = improve_tets(kept, params);
    EXPECT_EQ(k.boundary_vertex_moves, 0u);  // unset: the boundary is kept exactly
    EXPECT_LT(k.min_dihedral_after_deg, 20) << seed;
    params.boundary_deviation = 1e-3;
    const ImproveResult s = improve_tets(slid, params);
    EXPECT_GT(s.boundary_vertex_moves, 0u) << seed;
    EXPECT_GE(s.min_dihedral_after_deg, 20) << seed;
    EXPECT_TRUE(all_positive(slid)) << seed;
    EXPECT_NEAR(total_volume(slid), 1.0, 1e-12) << seed;  // the cube, whole
    // Every boundary face keeps its corners (renumbered with the removed inner points) and its tag;
    // each corner stays on the cube's sides it was on (a side's point in it, an edge's along it),
    // and the cube's corners stay where they are.
    ASSERT_EQ(slid.boundary_faces.size(), first_faces.size());
    EXPECT_EQ(slid.boundary_tags, tags);
    for (std::size_t f = 0; f < first_faces.size(); ++f)
      for (int c = 0; c < 3; ++c) {
        const Vec3& was = first[first_faces[f][c]];
        const Vec3& now = slid.points[slid.boundary_faces[f][c]];
        int sides = 0;
        for (int d = 0; d < 3; ++d)
          if (was[d] == 0 || was[d] == 1) {
            ++sides;
            EXPECT_NEAR(now[d], was[d], 1e-15) << seed;  // in the side's plane, to rounding
          }
        if (sides == 3) {
          EXPECT_EQ(now, was) << seed;
        }
      }
  }
}

TEST(BoundarySlides, StayOnTheSurfaceAsItWasAndWithinTheDeviationOfIt) {
  // TetGen's tets of a sphere whose vertices were moved at random and put back on it: poor faces
  // and tets. At goals of 28/150 deg the boundary as it is holds some tets back.
  const TriangleSoup sphere = test::jittered_icosphere(2, 0.04, 3);  // edges are about 0.3 long
  TetParams tet_params;
  tet_params.keep_surface = true;
  TetMesh kept = tetrahedralize_plc(plc_from_surface(sphere), tet_params), slid = kept;
  const TriangleSoup first = boundary_surface(kept);
  const double diagonal = bounding_box(first).diagonal().norm();
  ImproveParams params;
  params.goal_min_dihedral_deg = 28;
  params.goal_max_dihedral_deg = 150;
  const ImproveResult k = improve_tets(kept, params);
  params.boundary_deviation = 2e-3;
  const ImproveResult s = improve_tets(slid, params);
  EXPECT_GT(s.boundary_vertex_moves, 0u);
  EXPECT_GE(s.min_dihedral_after_deg, k.min_dihedral_after_deg);
  EXPECT_TRUE(all_positive(slid));
  const TriangleSoup now = boundary_surface(slid);
  ASSERT_EQ(now.triangles.size(), first.triangles.size());
  const auto distance = [](const Vec3& x, const TriangleSoup& surface) {
    double d = std::numeric_limits<double>::infinity();
    for (const Triangle& t : surface.triangles)
      d = std::min(d, (closest_point_on_triangle(x, surface.points[t[0]], surface.points[t[1]], surface.points[t[2]]) - x).norm());
    return d;
  };
  // Each vertex slides on the faces it began with: on the first surface, to rounding; and each
  // vertex's first place stays within the deviation of the faces around it (checked at every slide
  // of it or of a neighbour), so within it of the final surface.
  for (const Triangle& t : now.triangles)
    for (const std::uint32_t v : t) EXPECT_LE(distance(now.points[v], first), 1e-14 * diagonal);
  for (const Triangle& t : first.triangles)
    for (const std::uint32_t v : t) EXPECT_LE(distance(first.points[v], now), 2e-3 * diagonal);
  EXPECT_LE(s.boundary_max_displacement_relative, 1.0);
  EXPECT_GT(s.boundary_max_displacement_relative, 0.0);
}

}  // namespace
}  // namespace meshprep
