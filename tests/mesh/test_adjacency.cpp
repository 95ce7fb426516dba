#include <gtest/gtest.h>

#include <set>

#include "mesh/mesh_fixtures.hpp"
#include "sinew/mesh/tet_mesh.hpp"

namespace sinew::mesh {
namespace {

/// A shuffled box with some tets removed, so that node valences vary and some nodes are unused.
TetMesh irregular_mesh() {
  const TetMesh box = testing::shuffled(testing::box_mesh(4, 3, 3), 11);
  std::vector<Index> kept;
  for (Index t = 0; t < box.num_tets(); ++t) {
    if (t % 5 != 2) kept.push_back(t);
  }
  TetMesh mesh = box;
  mesh.tets = box.tets(kept, Eigen::all);
  mesh.region = IndexVector::Zero(mesh.tets.rows());
  return mesh;
}

std::vector<Index> csr_row(const std::vector<Index>& offsets, const std::vector<Index>& indices,
                           Index row) {
  return {indices.begin() + offsets[row], indices.begin() + offsets[row + 1]};
}

TEST(NodeTetAdjacency, MatchesBruteForce) {
  const TetMesh mesh = irregular_mesh();
  const NodeTetAdjacency adjacency = node_tet_adjacency(mesh.tets, mesh.num_nodes());
  ASSERT_EQ(adjacency.offsets.size(), static_cast<std::size_t>(mesh.num_nodes()) + 1);
  ASSERT_EQ(adjacency.indices.size(), static_cast<std::size_t>(4 * mesh.num_tets()));
  for (Index v = 0; v < mesh.num_nodes(); ++v) {
    std::vector<Index> expected;
    for (Index t = 0; t < mesh.num_tets(); ++t) {
      if ((mesh.tets.row(t).array() == v).any()) expected.push_back(t);
    }
    EXPECT_EQ(csr_row(adjacency.offsets, adjacency.indices, v), expected) << "node " << v;
  }
}

TEST(NodeNodeAdjacency, MatchesBruteForce) {
  const TetMesh mesh = irregular_mesh();
  const NodeNodeAdjacency adjacency = node_node_adjacency(mesh.tets, mesh.num_nodes());
  ASSERT_EQ(adjacency.offsets.size(), static_cast<std::size_t>(mesh.num_nodes()) + 1);
  std::vector<std::set<Index>> expected(static_cast<std::size_t>(mesh.num_nodes()));
  for (Index v = 0; v < mesh.num_nodes(); ++v) expected[v].insert(v);
  for (Index t = 0; t < mesh.num_tets(); ++t) {
    for (int a = 0; a < 4; ++a) {
      for (int b = 0; b < 4; ++b) expected[mesh.tets(t, a)].insert(mesh.tets(t, b));
    }
  }
  for (Index v = 0; v < mesh.num_nodes(); ++v) {
    EXPECT_EQ(csr_row(adjacency.offsets, adjacency.indices, v),
              std::vector<Index>(expected[v].begin(), expected[v].end()))
        << "node " << v;
  }
}

TEST(ReferencedNodes, IrregularMeshUsesASubset) {
  const TetMesh mesh = irregular_mesh();
  std::set<Index> expected(mesh.tets.data(), mesh.tets.data() + mesh.tets.size());
  EXPECT_EQ(referenced_nodes(mesh.tets), std::vector<Index>(expected.begin(), expected.end()));
}

}  // namespace
}  // namespace sinew::mesh
