#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "mesh/mesh_fixtures.hpp"
#include "sinew/core/error.hpp"
#include "sinew/mesh/tet_mesh.hpp"

namespace sinew::mesh {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

/// The message validate() throws, or "" when it accepts the mesh.
std::string validation_message(const TetMesh& mesh) {
  try {
    validate(mesh, "foo.msh");
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

/// A mesh of hand-placed tets over the given nodes, all in one region.
TetMesh hand_mesh(const Positions& nodes, const Tets& tets) {
  TetMesh mesh;
  mesh.rest = nodes;
  mesh.tets = tets;
  mesh.region = IndexVector::Zero(tets.rows());
  mesh.region_names = {"default"};
  return mesh;
}

TEST(Validate, AcceptsAStructuredBox) {
  EXPECT_EQ(validation_message(testing::box_mesh(3, 3, 3)), "");
}

TEST(Validate, RejectsAMeshWithoutTets) {
  EXPECT_THAT(validation_message(TetMesh{}), HasSubstr("mesh \"foo.msh\": no tetrahedra"));
}

TEST(Validate, RejectsInvertedTetsNamingThem) {
  TetMesh mesh = testing::box_mesh(3, 3, 3);
  std::swap(mesh.tets(17, 0), mesh.tets(17, 1));
  std::swap(mesh.tets(40, 2), mesh.tets(40, 3));
  EXPECT_THAT(validation_message(mesh),
              AllOf(HasSubstr("mesh \"foo.msh\": 2 inverted tetrahedra (negative volume)"),
                    HasSubstr("tet 17 (1-based 18"), HasSubstr("tet 40 (1-based 41")));
}

TEST(Validate, RejectsZeroVolumeTets) {
  TetMesh mesh = testing::box_mesh(2, 2, 2);
  // A tet that uses one node twice has zero volume.
  mesh.tets(5, 3) = mesh.tets(5, 0);
  EXPECT_THAT(validation_message(mesh),
              AllOf(HasSubstr("1 zero-volume tetrahedron"), HasSubstr("tet 5 (1-based 6")));
}

TEST(Validate, RejectsFlatTetsFromCoplanarNodes) {
  Positions x(4, 3);
  x << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0.3, 0.3, 0;
  Tets tets(1, 4);
  tets << 0, 1, 2, 3;
  TetMesh mesh = hand_mesh(x, tets);
  // A single flat tet has mean |V| = 0: every tet is at the threshold.
  EXPECT_THAT(validation_message(mesh), HasSubstr("zero-volume"));
}

TEST(Validate, RejectsDuplicateTets) {
  TetMesh mesh = testing::box_mesh(2, 2, 2);
  const Index last = mesh.num_tets();
  mesh.tets.conservativeResize(last + 1, 4);
  mesh.tets.row(last) << mesh.tets(3, 1), mesh.tets(3, 2), mesh.tets(3, 0), mesh.tets(3, 3);
  mesh.region = IndexVector::Zero(last + 1);
  EXPECT_THAT(validation_message(mesh),
              AllOf(HasSubstr("1 duplicate tetrahedron (same four nodes)"),
                    HasSubstr("tet " + std::to_string(last) + " "), HasSubstr("repeats tet 3")));
}

TEST(Validate, RejectsNodeIndicesOutOfRange) {
  TetMesh mesh = testing::box_mesh(2, 2, 2);
  mesh.tets(4, 2) = mesh.num_nodes();
  mesh.tets(9, 0) = -1;
  EXPECT_THAT(validation_message(mesh),
              AllOf(HasSubstr("2 tetrahedra with node indices"), HasSubstr("out of range"),
                    HasSubstr("tet 4 (1-based 5"), HasSubstr("tet 9 (1-based 10")));
}

TEST(Validate, RejectsBadRegionsAndSets) {
  TetMesh bad_region = testing::box_mesh(1, 1, 1);
  bad_region.region(2) = 1;
  EXPECT_THAT(validation_message(bad_region), HasSubstr("region id"));

  TetMesh short_region = testing::box_mesh(1, 1, 1);
  short_region.region.resize(2);
  EXPECT_THAT(validation_message(short_region), HasSubstr("region vector has 2 entries"));

  TetMesh bad_node_set = testing::box_mesh(1, 1, 1);
  bad_node_set.node_sets["top"] = {0, 99};
  EXPECT_THAT(validation_message(bad_node_set), HasSubstr("node set \"top\""));

  TetMesh bad_face_set = testing::box_mesh(1, 1, 1);
  bad_face_set.face_sets["top"] = Triangles::Constant(1, 3, 99);
  EXPECT_THAT(validation_message(bad_face_set), HasSubstr("face set \"top\""));
}

TEST(Validate, RejectsNonFiniteCoordinates) {
  TetMesh mesh = testing::box_mesh(1, 1, 1);
  mesh.rest(3, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(validation_message(mesh), HasSubstr("node 3 (1-based 4)"));
}

TEST(Validate, RejectsAFaceSharedByThreeTets) {
  // Face (0, 1, 2) in the plane z = 0 with apexes 3 and 5 above it and 4 below.
  Positions x(6, 3);
  x << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0.2, 0.2, 1, 0.2, 0.2, -1, 0.3, 0.1, 2;
  Tets tets(3, 4);
  tets << 0, 1, 2, 3, 0, 2, 1, 4, 0, 1, 2, 5;
  EXPECT_THAT(
      validation_message(hand_mesh(x, tets)),
      AllOf(HasSubstr("1 face shared by more than two tetrahedra"), HasSubstr("non-manifold")));
}

TEST(Validate, RejectsTwoTetsSharingOnlyAnEdge) {
  // Edge (0, 1) along x; one tet on the +y side, one on the -y side.
  Positions x(6, 3);
  x << 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, 0.5, 1, 0.5, -1, 0, 0.5, -0.5, -1;
  Tets tets(2, 4);
  tets << 0, 1, 2, 3, 0, 1, 4, 5;
  TetMesh mesh = hand_mesh(x, tets);
  orient_positively(mesh.rest, mesh.tets);
  EXPECT_THAT(
      validation_message(mesh),
      AllOf(HasSubstr("1 boundary edge not shared by exactly two boundary triangles"),
            HasSubstr("edge (0, 1) in 4 boundary triangles"), HasSubstr("non-manifold boundary")));
}

TEST(Validate, RejectsTwoTetsSharingOnlyAVertex) {
  Positions x(7, 3);
  x << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, -1, 0, 0, 0, -1;
  Tets tets(2, 4);
  tets << 0, 1, 2, 3, 0, 4, 5, 6;
  TetMesh mesh = hand_mesh(x, tets);
  orient_positively(mesh.rest, mesh.tets);
  EXPECT_THAT(validation_message(mesh),
              AllOf(HasSubstr("1 boundary node where separate sheets of the boundary meet"),
                    HasSubstr("node 0 (1-based 1)"), HasSubstr("non-manifold boundary")));
}

TEST(Validate, AcceptsSeparateBodies) {
  Positions x(8, 3);
  x << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 5, 0, 0, 6, 0, 0, 5, 1, 0, 5, 0, 1;
  Tets tets(2, 4);
  tets << 0, 1, 2, 3, 4, 5, 6, 7;
  EXPECT_EQ(validation_message(hand_mesh(x, tets)), "");
}

TEST(Validate, ListsOnlyTheFirstFewOffenders) {
  TetMesh mesh = testing::box_mesh(3, 3, 3);
  for (Index t = 0; t < 10; ++t) std::swap(mesh.tets(t, 0), mesh.tets(t, 1));
  const std::string message = validation_message(mesh);
  EXPECT_THAT(message, HasSubstr("10 inverted tetrahedra"));
  EXPECT_THAT(message, HasSubstr("tet 2 (1-based 3"));
  EXPECT_THAT(message, ::testing::Not(HasSubstr("tet 3 (1-based 4")));
}

}  // namespace
}  // namespace sinew::mesh
