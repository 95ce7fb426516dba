#include "sinew/mesh/tet_mesh.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mesh/mesh_fixtures.hpp"
#include "sinew/core/error.hpp"

namespace sinew::mesh {
namespace {

using ::testing::HasSubstr;

Positions reference_tet_nodes() {
  Positions x(4, 3);
  x << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  return x;
}

TEST(SignedVolume, ReferenceTetIsOneSixthAndSwapFlipsSign) {
  const Positions x = reference_tet_nodes();
  Tets tets(2, 4);
  tets << 0, 1, 2, 3, 0, 1, 3, 2;
  EXPECT_DOUBLE_EQ(signed_volume(x, tets, 0), 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(signed_volume(x, tets, 1), -1.0 / 6.0);
}

TEST(OrientPositively, FlipsOnlyNegativeTets) {
  const Positions x = reference_tet_nodes();
  Tets tets(3, 4);
  tets << 0, 1, 2, 3, 0, 1, 3, 2, 1, 0, 2, 3;
  EXPECT_EQ(orient_positively(x, tets), 2);
  for (Index t = 0; t < 3; ++t) EXPECT_GT(signed_volume(x, tets, t), 0);
  EXPECT_EQ(tets.row(0), (Eigen::RowVector4i(0, 1, 2, 3)));  // untouched
  EXPECT_EQ(orient_positively(x, tets), 0);
}

TEST(RegionId, FindsNamesAndListsKnownOnesWhenMissing) {
  TetMesh mesh;
  mesh.region_names = {"rubber", "steel"};
  EXPECT_EQ(mesh.region_id("steel"), 1);
  try {
    mesh.region_id("wood");
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("\"wood\""));
    EXPECT_THAT(error.what(), HasSubstr("\"rubber\", \"steel\""));
  }
}

TEST(ReferencedNodes, SortedAndUnique) {
  Tets tets(2, 4);
  tets << 7, 2, 5, 3, 3, 9, 2, 5;
  EXPECT_EQ(referenced_nodes(tets), (std::vector<Index>{2, 3, 5, 7, 9}));
  EXPECT_TRUE(referenced_nodes(Tets(0, 4)).empty());
}

TEST(StructuredBox, FixtureIsAValidMeshOfTheRightVolume) {
  const TetMesh box = testing::box_mesh(3, 2, 4, 0.5);
  EXPECT_EQ(box.num_tets(), 6 * 3 * 2 * 4);
  EXPECT_NEAR(testing::total_volume(box.rest, box.tets), 1.5 * 1.0 * 2.0, 1e-12);
  EXPECT_NO_THROW(validate(box, "structured box"));
  EXPECT_NO_THROW(validate(testing::shuffled(box, 3), "shuffled box"));
}

}  // namespace
}  // namespace sinew::mesh
