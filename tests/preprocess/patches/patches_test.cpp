// Boundary patches (patches.h): found from the creases, kept from the file, edited, and carried
// through the stages that move or replace faces (simplify, enhance), whose collapses and flips
// must never merge two patches across their border.
#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "meshprep/core/mesh_patches.h"
#include "meshprep/preprocess/enhance/enhance.h"
#include "meshprep/preprocess/patches/patches.h"
#include "meshprep/preprocess/simplify/simplify.h"
#include "meshprep/quality/patch_table.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string>

namespace meshprep {
namespace {

double area_of(const TriangleSoup& s) {
  double area = 0;
  for (const Triangle& t : s.triangles) area += 0.5 * (s.points[t[1]] - s.points[t[0]]).cross(s.points[t[2]] - s.points[t[0]]).norm();
  return area;
}

std::map<std::string, double> areas_by_name(const TriangleSoup& s) {
  std::map<std::string, double> areas;
  for (const PatchRow& row : patch_table(s)) areas[row.name] = row.area;
  return areas;
}

// The edges between two patches, as segments.
std::vector<std::pair<Vec3, Vec3>> border_segments(const TriangleSoup& s) {
  const TriMesh mesh = mesh_from_soup(s);
  const FacePatches patches(mesh);
  std::vector<std::pair<Vec3, Vec3>> segments;
  for (const auto e : mesh.edges())
    if (patches.border(e))
      segments.emplace_back(to_eigen(mesh.point(mesh.to_vertex_handle(mesh.halfedge_handle(e, 0)))),
                            to_eigen(mesh.point(mesh.to_vertex_handle(mesh.halfedge_handle(e, 1)))));
  return segments;
}

double distance_to_segments(const Vec3& p, const std::vector<std::pair<Vec3, Vec3>>& segments) {
  double nearest = INFINITY;
  for (const auto& [a, b] : segments) {
    const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    nearest = std::min(nearest, (a + t * (b - a) - p).norm());
  }
  return nearest;
}

TriangleSoup transformed(TriangleSoup s, double scale) {
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  for (Vec3& p : s.points) p = scale * (rotation * p);
  return s;
}

std::size_t patch_count(TriangleSoup s) { return find_patches(s, {}).patches; }

TEST(Patches, ABoxHasSixACylinderThreeAndASmoothSurfaceOne) {
  TriangleSoup box = test::subdivided_cube(4);
  const PatchResult r = find_patches(box, {});
  EXPECT_TRUE(r.segmented);
  EXPECT_EQ(r.patches, 6u);
  for (const PatchRow& row : patch_table(box)) {
    EXPECT_NEAR(row.area, 16.0, 1e-12) << row.name;  // each side of the cube [0, 4]^3
    EXPECT_NEAR(row.normal_spread_deg, 0.0, 1e-6) << row.name;
  }
  EXPECT_EQ(patch_count(test::cylinder_with_fan_caps(24)), 3u);
  EXPECT_EQ(patch_count(test::icosphere(3)), 1u);
  EXPECT_EQ(patch_count(test::torus(32, 16)), 1u);
}

// A closed patch's normals point every way, wherever it lies: its area vectors sum to rounding
// noise, which has no direction to measure a spread from.
TEST(Patches, AClosedPatchSpreadsHalfATurnAtTheOriginAndFarFromIt) {
  for (const double offset : {0.0, 1e9}) {
    TriangleSoup sphere = test::icosphere(3);
    for (Vec3& p : sphere.points) p += Vec3(offset, -offset, offset);
    find_patches(sphere, {});
    const std::vector<PatchRow> table = patch_table(sphere);
    ASSERT_EQ(table.size(), 1u);
    EXPECT_EQ(table[0].normal_spread_deg, 180.0) << "offset " << offset;
  }
}

TEST(Patches, AreNamedByDecreasingAreaAndTheirAreasSumToTheSurfaces) {
  TriangleSoup cylinder = test::cylinder_with_fan_caps(24);
  for (Vec3& p : cylinder.points) p.z() *= 5;  // the side is now the largest patch
  find_patches(cylinder, {});
  const std::vector<PatchRow> table = patch_table(cylinder);
  ASSERT_EQ(table.size(), 3u);
  EXPECT_EQ(table[0].name, "patch_1");
  EXPECT_GT(table[0].normal_spread_deg, 80.0);  // the side turns all the way round
  EXPECT_GE(table[0].area, table[1].area);
  EXPECT_GE(table[1].area, table[2].area);
  double sum = 0;
  for (const PatchRow& row : table) sum += row.area;
  EXPECT_NEAR(sum, area_of(cylinder), 1e-9 * area_of(cylinder));
}

// The same patches whatever the units and the orientation: the segmentation uses angles and
// lengths relative to the median edge only.
TEST(Patches, TheSameUnderRotationAndScaling) {
  const TriangleSoup fandisk = read_soup(std::string(MESHPREP_EXAMPLES_DATA_DIR) + "/fandisk.off");
  TriangleSoup reference = fandisk;
  find_patches(reference, {});
  EXPECT_EQ(patch_table(reference).size(), 10u);  // the sharp edges of the fan disk bound 10 faces
  for (const TriangleSoup& part : {test::subdivided_cube(3), test::cylinder_with_fan_caps(30), fandisk}) {
    TriangleSoup original = part;
    find_patches(original, {});
    for (const double scale : {1e-3, 1.0, 1e3}) {
      TriangleSoup moved = transformed(part, scale);
      find_patches(moved, {});
      EXPECT_EQ(moved.patches, original.patches) << "scale " << scale;
    }
  }
}

TEST(Patches, TheFilesPatchesAreKeptUnlessResegmented) {
  TriangleSoup box = test::subdivided_cube(2);
  box.patches.assign(box.triangles.size(), 1);
  for (std::size_t f = 0; f < box.triangles.size() / 2; ++f) box.patches[f] = 2;
  box.patch_names = {{1, "rest"}, {2, "half"}};
  TriangleSoup kept = box;
  const PatchResult r = find_patches(kept, {});
  EXPECT_FALSE(r.segmented);
  EXPECT_EQ(kept.patches, box.patches);
  PatchParams again;
  again.resegment = true;
  EXPECT_EQ(find_patches(box, again).patches, 6u);
}

TEST(Patches, MergesAndRenamesAndWhatTheyRefuse) {
  TriangleSoup box = test::subdivided_cube(2);
  PatchParams edits;
  edits.merges = {{"patch_1", "patch_2", "patch_3"}};
  edits.renames = {{"patch_1", "three sides"}, {"patch_6", "Lid"}};
  const PatchResult r = find_patches(box, edits);
  EXPECT_EQ(r.patches, 4u);
  EXPECT_EQ(r.merged, 2u);
  const std::map<std::string, double> areas = areas_by_name(box);
  EXPECT_NEAR(areas.at("three_sides"), 12.0, 1e-12);  // the name made to follow the rule
  EXPECT_NEAR(areas.at("Lid"), 4.0, 1e-12);
  ASSERT_EQ(r.renamed.size(), 2u);
  EXPECT_EQ(r.renamed[0].to, "three_sides");

  const auto message = [](const PatchParams& p) {
    TriangleSoup cube = test::subdivided_cube(2);
    try {
      find_patches(cube, p);
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  PatchParams unknown;
  unknown.renames = {{"inlet", "x"}};
  EXPECT_NE(message(unknown).find("no patch is named 'inlet' (the patches: patch_1, patch_2"), std::string::npos)
      << message(unknown);
  PatchParams taken;
  taken.renames = {{"patch_1", "patch_2"}};
  EXPECT_NE(message(taken).find("already"), std::string::npos);
  PatchParams lone;
  lone.merges = {{"patch_1"}};
  EXPECT_FALSE(message(lone).empty());
  // The same refusals without a surface, before any work.
  EXPECT_THROW(check_patch_edits({{1, "top"}}, unknown), InvalidInput);
  EXPECT_NO_THROW(check_patch_edits({{1, "inlet"}}, unknown));
}

TEST(Patches, ANonManifoldSurfaceIsRefused) {
  TriangleSoup fin = test::cube();
  fin.points.push_back({0.5, 0.5, 2});
  fin.triangles.push_back({0, 1, 8});  // a third face on the edge 0-1
  EXPECT_THROW(find_patches(fin, {}), InvalidInput);
}

// Two hemispheres of a sphere named as patches: their border is no crease, so only the stages'
// respect for patch borders keeps it. Through simplification to 30 % and the enhancement, each
// face keeps its hemisphere and each hemisphere's area stays within 0.5 % of the input's.
TEST(Patches, SimplifyAndEnhanceKeepEachPatchAndItsArea) {
  TriangleSoup sphere = test::icosphere(4);
  sphere.patches.resize(sphere.triangles.size());
  for (std::size_t f = 0; f < sphere.triangles.size(); ++f) {
    const Triangle& t = sphere.triangles[f];
    const double z = sphere.points[t[0]].z() + sphere.points[t[1]].z() + sphere.points[t[2]].z();
    sphere.patches[f] = z > 0 ? 1 : 2;
  }
  sphere.patch_names = {{1, "north"}, {2, "south"}};
  const std::map<std::string, double> before = areas_by_name(sphere);
  TriMesh mesh = mesh_from_soup(sphere);
  SimplifyParams simplifying;
  simplifying.keep_ratio = 0.3;
  simplify(mesh, simplifying);
  EnhanceParams enhancing;
  enhance(mesh, &sphere, enhancing);
  const TriangleSoup after = soup_from_mesh(mesh);
  ASSERT_EQ(after.patches.size(), after.triangles.size());
  EXPECT_LT(after.triangles.size(), sphere.triangles.size() / 2);
  for (std::size_t f = 0; f < after.triangles.size(); ++f) {
    const Triangle& t = after.triangles[f];
    const double z = after.points[t[0]].z() + after.points[t[1]].z() + after.points[t[2]].z();
    // The border's zigzag: a face may touch the equator's other side, never lie beyond it.
    EXPECT_TRUE(after.patches[f] == 1 ? z > -0.3 : z < 0.3) << "face " << f;
  }
  // Every corner of the border left lies on the input's border: a collapse along it drops a
  // corner, the enhancement slides one along it, nothing moves it off (round-off aside).
  const std::vector<std::pair<Vec3, Vec3>> input_border = border_segments(sphere);
  double farthest = 0;
  for (const auto& [a, b] : border_segments(after))
    farthest = std::max({farthest, distance_to_segments(a, input_border), distance_to_segments(b, input_border)});
  EXPECT_LT(farthest, 1e-12);
  const std::map<std::string, double> areas = areas_by_name(after);
  for (const auto& [name, area] : before) EXPECT_NEAR(areas.at(name), area, 5e-3 * area) << name;
}

}  // namespace
}  // namespace meshprep
