// Boundary patches read from and written to the surface formats (io.h): OBJ groups, the solids of
// an ASCII STL, a PLY face property; each writer's output read back by our own reader.
#include "meshprep/core/errors.h"
#include "meshprep/core/io.h"
#include "scratch_dir.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <string>

namespace meshprep {
namespace {

using PatchIo = test::ScratchDirTest;

// Faces per patch name.
std::map<std::string, std::size_t> faces_by_name(const TriangleSoup& soup) {
  std::map<std::string, std::size_t> faces;
  for (const int tag : soup.patches) ++faces[soup.patch_names.at(tag)];
  return faces;
}

// The unit cube with one patch per side, named after the side.
TriangleSoup named_cube() {
  TriangleSoup soup = test::cube();
  const char* sides[] = {"bottom", "top", "front", "back", "left", "right"};
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) soup.patches.push_back(static_cast<int>(f / 2) + 1);
  for (int side = 0; side < 6; ++side) soup.patch_names[side + 1] = sides[side];
  return soup;
}

TEST_F(PatchIo, ObjGroupsArePatchesAndFacesBeforeTheFirstGroupAreDefault) {
  const std::string obj = file("g.obj",
                               "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                               "f 1 3 2\n"
                               "g inlet\nf 1 2 4\n"
                               "o outlet wall\nf 1 4 3\n"
                               "g inlet\nf 2 3 4\n");
  ReadReport report;
  const TriangleSoup soup = read_soup(obj, &report);
  ASSERT_EQ(soup.patches.size(), 4u);
  EXPECT_EQ(report.patches_from, "obj groups");
  const std::map<std::string, std::size_t> expected{{"default", 1}, {"inlet", 2}, {"outlet", 1}};
  EXPECT_EQ(faces_by_name(soup), expected);  // of "o outlet wall" the first word
}

TEST_F(PatchIo, OneGroupIsThePartsNameNotAPatch) {
  const std::string obj = file("one.obj", "o Cube\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  ReadReport report;
  const TriangleSoup soup = read_soup(obj, &report);
  EXPECT_TRUE(soup.patches.empty());
  EXPECT_TRUE(soup.patch_names.empty());
  EXPECT_TRUE(report.patches_from.empty());
}

TEST_F(PatchIo, TheSolidsOfAnAsciiStlArePatchesNamedByTheirSolidLines) {
  std::string stl;
  const char* facets[][3] = {{"0 0 0", "0 1 0", "1 0 0"}, {"0 0 0", "1 0 0", "0 0 1"},
                             {"0 0 0", "0 0 1", "0 1 0"}, {"1 0 0", "0 1 0", "0 0 1"}};
  const char* solids[] = {"fixed end", "", "fixed end", "Träger"};
  for (int s = 0; s < 4; ++s) {
    stl += std::string("solid ") + solids[s] + "\n facet normal 0 0 0\n  outer loop\n";
    for (const char* corner : facets[s]) stl += std::string("   vertex ") + corner + "\n";
    stl += "  endloop\n endfacet\nendsolid\n";
  }
  ReadReport report;
  const TriangleSoup soup = read_soup(file("multi.stl", stl), &report);
  EXPECT_EQ(report.patches_from, "stl solids");
  const std::map<std::string, std::size_t> expected{{"fixed_end", 2}, {"solid_2", 1}, {"Tr_ger", 1}};
  EXPECT_EQ(faces_by_name(soup), expected);
  EXPECT_EQ(report.renamed_patches.size(), 2u);  // "fixed end" and "Träger": reported
}

TEST_F(PatchIo, APlyLabelCountedFromZeroBecomesTagsFromOneWithTheCommentsNames) {
  const std::string ply = file("l.ply",
                               "ply\nformat ascii 1.0\ncomment patch 0 lid\nelement vertex 4\n"
                               "property float x\nproperty float y\nproperty float z\n"
                               "element face 3\nproperty uchar label\nproperty list uchar int vertex_indices\nend_header\n"
                               "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 3 0 1 2\n1 3 0 2 3\n0 4 0 1 2 3\n");
  ReadReport report;
  const TriangleSoup soup = read_soup(ply, &report);
  EXPECT_EQ(report.patches_from, "ply face property 'label'");
  EXPECT_EQ(soup.patches, (std::vector<int>{1, 2, 1, 1}));  // the quad's two triangles keep its label
  EXPECT_EQ(soup.patch_names.at(1), "lid");
  EXPECT_EQ(soup.patch_names.at(2), "patch_1");
}

TEST_F(PatchIo, EveryWriterThatHoldsPatchesReadsBackTheSameNamesAndFaces) {
  const TriangleSoup cube = named_cube();
  for (const char* name : {"c.obj", "c.ply", "c.stl"}) {
    for (const bool binary : {false, true}) {
      WriteOptions options;
      options.binary = binary;
      if (binary && std::string(name) == "c.stl") continue;  // binary STL has no place for them
      write_soup(cube, path(name), options);
      const TriangleSoup back = read_soup(path(name));
      EXPECT_EQ(faces_by_name(back), faces_by_name(cube)) << name << (binary ? " binary" : "");
    }
  }
  // PLY keeps the face order and the tags themselves.
  EXPECT_EQ(read_soup(path("c.ply")).patches, cube.patches);
}

TEST_F(PatchIo, FormatsWithoutPatchesDropThem) {
  write_soup(named_cube(), path("c.off"));
  EXPECT_TRUE(read_soup(path("c.off")).patches.empty());
  WriteOptions binary;
  binary.binary = true;
  write_soup(named_cube(), path("b.stl"), binary);
  EXPECT_TRUE(read_soup(path("b.stl")).patches.empty());
}

TEST_F(PatchIo, ANameAgainstTheRuleOrAPatchCountOffIsRefusedBeforeWriting) {
  TriangleSoup cube = named_cube();
  cube.patch_names[1] = "two words";
  EXPECT_THROW(write_soup(cube, path("bad.ply")), InvalidInput);
  cube = named_cube();
  cube.patches.pop_back();
  EXPECT_THROW(write_soup(cube, path("bad.obj")), InvalidInput);
  EXPECT_FALSE(std::filesystem::exists(path("bad.ply")));
  EXPECT_FALSE(std::filesystem::exists(path("bad.obj")));
}

}  // namespace
}  // namespace meshprep
