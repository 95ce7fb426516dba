/// @file test_tet_mesh_bytes.cpp
/// mesh/tet_mesh_bytes.hpp: a mesh sent as bytes (rank 0 to the other MPI ranks) reads back to
/// the last bit, every member included; bytes cut short, with more after the mesh, or with an
/// impossible count are refused.

#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "mesh_fixtures.hpp"
#include "sinew/mesh/tet_mesh_bytes.hpp"

namespace sinew::mesh {
namespace {

/// A 3 x 2 x 2 box with two regions, sets, a node field and a skipped one, and positions that
/// no decimal text would keep exactly.
TetMesh every_member_mesh() {
  TetMesh mesh = testing::box_mesh(3, 2, 2, Vector3(0, 0, 0), Vector3(1.0 / 3.0, 0.7, std::acos(-1.0)));
  mesh.region_names = {"soft", "hard \"core\""};
  for (Index t = 0; t < mesh.num_tets(); ++t) mesh.region[t] = t % 3 == 0 ? 1 : 0;
  mesh.node_sets["bottom"] = {0, 1, 2, 5};
  mesh.node_sets["empty"] = {};
  mesh.face_sets["top"] = Triangles(2, 3);
  mesh.face_sets["top"] << 0, 1, 2, 2, 1, 3;
  mesh.node_fields["temperature"] = VectorX::LinSpaced(mesh.num_nodes(), -1e-300, 1e300);
  mesh.skipped_node_fields["velocity"] = "3 components per node, not 1";
  return mesh;
}

TEST(TetMeshBytes, AMeshReadsBackExactly) {
  const TetMesh mesh = every_member_mesh();
  const std::string bytes = tet_mesh_bytes(mesh);
  const TetMesh back = tet_mesh_from_bytes(bytes);
  EXPECT_EQ(back.rest, mesh.rest);
  EXPECT_EQ(back.tets, mesh.tets);
  EXPECT_EQ(back.region, mesh.region);
  EXPECT_EQ(back.region_names, mesh.region_names);
  EXPECT_EQ(back.node_sets, mesh.node_sets);
  ASSERT_EQ(back.face_sets.size(), 1u);
  EXPECT_EQ(back.face_sets.at("top"), mesh.face_sets.at("top"));
  ASSERT_EQ(back.node_fields.size(), 1u);
  EXPECT_EQ(back.node_fields.at("temperature"), mesh.node_fields.at("temperature"));
  EXPECT_EQ(back.skipped_node_fields, mesh.skipped_node_fields);
  EXPECT_EQ(tet_mesh_bytes(back), bytes);
  // An empty mesh too.
  const TetMesh none = tet_mesh_from_bytes(tet_mesh_bytes(TetMesh{}));
  EXPECT_EQ(none.num_nodes(), 0);
  EXPECT_EQ(none.num_tets(), 0);
}

TEST(TetMeshBytes, BytesCutShortOrWithMoreAfterOrAnImpossibleCountAreRefused) {
  const std::string bytes = tet_mesh_bytes(every_member_mesh());
  for (std::size_t cut : {std::size_t{0}, std::size_t{7}, std::size_t{8}, std::size_t{100}, bytes.size() / 2, bytes.size() - 1}) {
    try {
      tet_mesh_from_bytes(std::string_view(bytes).substr(0, cut));
      ADD_FAILURE() << "bytes cut at " << cut << " read back";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("a mesh's bytes do not read back"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(tet_mesh_from_bytes(bytes + "x"), Error);
  // The positions' row count made huge: refused before any allocation of that size.
  std::string huge = bytes;
  const std::uint64_t rows = std::uint64_t{1} << 60;
  std::memcpy(huge.data(), &rows, sizeof(rows));
  EXPECT_THROW(tet_mesh_from_bytes(huge), Error);
  // The tets' width (the second count after the positions) other than 4.
  std::string wide = bytes;
  const TetMesh mesh = every_member_mesh();
  const std::size_t tets_at = 16 + static_cast<std::size_t>(mesh.rest.size()) * sizeof(double);
  const std::uint64_t five = 5;
  std::memcpy(wide.data() + tets_at + 8, &five, sizeof(five));
  EXPECT_THROW(tet_mesh_from_bytes(wide), Error);
}

}  // namespace
}  // namespace sinew::mesh
