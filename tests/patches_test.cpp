// Boundary patches: the naming rule (patch_names.h) and the face property that carries patches on
// the halfedge mesh (mesh_patches.h) through the soup conversions.
#include "meshprep/core/errors.h"
#include "meshprep/core/mesh_patches.h"
#include "meshprep/core/patch_names.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

namespace meshprep {
namespace {

TEST(PatchNames, TheRuleEveryFormatHolds) {
  EXPECT_TRUE(is_valid_name("top"));
  EXPECT_TRUE(is_valid_name("Fixed_End_2"));
  EXPECT_FALSE(is_valid_name(""));
  EXPECT_FALSE(is_valid_name("2nd"));
  EXPECT_FALSE(is_valid_name("_x"));
  EXPECT_FALSE(is_valid_name("a b"));
  EXPECT_FALSE(is_valid_name(std::string(kMaxNameLength + 1, 'a')));
  EXPECT_TRUE(is_valid_name(std::string(kMaxNameLength, 'a')));
}

TEST(PatchNames, SpacesPunctuationAndNonAsciiBecomeOneUnderscore) {
  EXPECT_EQ(sanitized_name("Tr\xC3\xA4ger links"), "Tr_ger_links");  // "Träger links" in UTF-8
  EXPECT_EQ(sanitized_name("1st face"), "p_1st_face");
  EXPECT_EQ(sanitized_name(""), "p_");
  EXPECT_EQ(sanitized_name("in-let.3"), "in_let_3");
  EXPECT_EQ(sanitized_name(std::string(100, 'x')).size(), kMaxNameLength);
  for (const char* name : {"Tr\xC3\xA4ger links", "1st face", "", "\"quoted\"", "a\nb"})
    EXPECT_TRUE(is_valid_name(sanitized_name(name))) << name;
}

TEST(PatchNames, NamesEqualButForCaseAreMadeDistinctAndReported) {
  TagNames names{{1, "top"}, {2, "TOP"}, {3, "side wall"}, {4, "bottom"}};
  const std::vector<RenamedTag> renamed = sanitize_names(names);
  EXPECT_EQ(names.at(1), "top");
  EXPECT_EQ(names.at(2), "TOP_2");
  EXPECT_EQ(names.at(3), "side_wall");
  EXPECT_EQ(names.at(4), "bottom");
  ASSERT_EQ(renamed.size(), 2u);
  EXPECT_EQ(renamed[0].tag, 2);
  EXPECT_EQ(renamed[0].from, "TOP");
  EXPECT_EQ(renamed[1].to, "side_wall");
  EXPECT_EQ(tag_name(names, 3, "boundary"), "side_wall");
  EXPECT_EQ(tag_name(names, 7, "boundary"), "boundary_7");
}

TEST(MeshPatches, TravelThroughTheHalfedgeMeshAndBack) {
  TriangleSoup soup = test::cube();
  soup.patches.resize(soup.triangles.size());
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) soup.patches[f] = static_cast<int>(f / 2) + 1;
  soup.patch_names = {{1, "a"}, {6, "f"}};
  TriMesh mesh = mesh_from_soup(soup);
  const FacePatches patches(mesh);
  ASSERT_TRUE(patches.present());
  std::size_t borders = 0;
  for (const auto e : mesh.edges()) borders += patches.border(e);
  EXPECT_EQ(borders, 12u);  // the cube's edges; each face's diagonal is inside its patch
  const TriangleSoup back = soup_from_mesh(mesh);
  EXPECT_EQ(back.patches, soup.patches);
  EXPECT_EQ(back.patch_names, soup.patch_names);

  // A deleted face's patch is skipped with it.
  mesh.delete_face(TriMesh::FaceHandle(0), false);
  EXPECT_EQ(soup_from_mesh(mesh).patches.front(), 1);
  EXPECT_EQ(soup_from_mesh(mesh).patches.size(), soup.triangles.size() - 1);
}

TEST(MeshPatches, AMeshWithoutPatchesHasNone) {
  const TriMesh mesh = mesh_from_soup(test::cube());
  const FacePatches patches(mesh);
  EXPECT_FALSE(patches.present());
  EXPECT_EQ(patches.of(TriMesh::FaceHandle(0)), 0);
  EXPECT_TRUE(soup_from_mesh(mesh).patches.empty());
}

TEST(MeshPatches, APatchCountOtherThanTheFacesIsRefused) {
  TriangleSoup soup = test::cube();
  soup.patches = {1, 2};
  EXPECT_THROW(mesh_from_soup(soup), InvalidInput);
}

}  // namespace
}  // namespace meshprep
