/// @file test_partition.cpp
/// The tets' partition among ranks (parallel/partition.hpp), computed in one process: every tet in
/// one part, balanced work, compact connected parts that cut few faces, the weights honoured, the
/// same result every time, and clear errors.

#include "sinew/parallel/partition.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <vector>

#include "sinew/core/error.hpp"
#include "support/box_mesh.hpp"

namespace sinew::parallel {
namespace {

/// Pairs of tets that share a face, each once.
std::vector<std::pair<Index, Index>> face_neighbours(const Tets& tets) {
  std::map<std::array<Index, 3>, std::vector<Index>> faces;
  for (Index t = 0; t < tets.rows(); ++t)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<Index, 3> face{};
      int k = 0;
      for (int c = 0; c < 4; ++c)
        if (c != skip) face[static_cast<std::size_t>(k++)] = tets(t, c);
      std::sort(face.begin(), face.end());
      faces[face].push_back(t);
    }
  std::vector<std::pair<Index, Index>> pairs;
  for (const auto& [face, users] : faces)
    if (users.size() == 2) pairs.emplace_back(users[0], users[1]);
  return pairs;
}

/// The number of connected pieces (through shared faces) of the tets of `part`.
int connected_pieces(const Tets& tets, const std::vector<int>& owner, int part) {
  std::vector<Index> parent(static_cast<std::size_t>(tets.rows()));
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](Index t) {
    while (parent[static_cast<std::size_t>(t)] != t) t = parent[static_cast<std::size_t>(t)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(t)])];
    return t;
  };
  for (const auto& [a, b] : face_neighbours(tets))
    if (owner[static_cast<std::size_t>(a)] == part && owner[static_cast<std::size_t>(b)] == part) parent[static_cast<std::size_t>(root(a))] = root(b);
  int pieces = 0;
  for (Index t = 0; t < tets.rows(); ++t)
    if (owner[static_cast<std::size_t>(t)] == part && root(t) == t) ++pieces;
  return pieces;
}

TEST(PartitionTets, CutsABarIntoBalancedConnectedPartsAcrossItsLength) {
  // A bar of 16 x 4 x 4 cubes (6 tets each): a cut across the bar crosses 4 x 4 squares, 32
  // triangles; parts taken in the tets' numbering would be slabs too, but any partition of
  // scattered tets would cut thousands of faces.
  const mesh::TetMesh bar = testing::box_mesh(16, 4, 4, 1.0);
  const auto num_tets = static_cast<std::size_t>(bar.tets.rows());
  const auto neighbours = face_neighbours(bar.tets);
  for (const int parts : {2, 3, 4}) {
    SCOPED_TRACE(std::to_string(parts) + " parts");
    const std::vector<int> owner = partition_tets(bar.tets, {}, parts);
    ASSERT_EQ(owner.size(), num_tets);
    std::vector<std::size_t> count(static_cast<std::size_t>(parts), 0);
    for (const int o : owner) {
      ASSERT_GE(o, 0);
      ASSERT_LT(o, parts);
      ++count[static_cast<std::size_t>(o)];
    }
    for (const std::size_t c : count) EXPECT_NEAR(static_cast<double>(c), double(num_tets) / parts, 0.05 * double(num_tets) / parts);
    std::size_t cut = 0;
    for (const auto& [a, b] : neighbours) cut += owner[static_cast<std::size_t>(a)] != owner[static_cast<std::size_t>(b)];
    EXPECT_LE(cut, static_cast<std::size_t>(3 * 32 * (parts - 1))) << "faces between parts";
    for (int part = 0; part < parts; ++part) EXPECT_EQ(connected_pieces(bar.tets, owner, part), 1) << "part " << part;
    EXPECT_EQ(partition_tets(bar.tets, {}, parts), owner) << "the same partition every time";
  }
}

TEST(PartitionTets, BalancesTheWeightsNotTheCounts) {
  // The tets of the bar's first quarter weigh 8 (deformable, as the model weighs them), the rest 1:
  // two parts of equal weight give the heavy quarter a part nearly to itself.
  const mesh::TetMesh bar = testing::box_mesh(16, 4, 4, 1.0);
  std::vector<int> weights(static_cast<std::size_t>(bar.tets.rows()), 1);
  for (Index t = 0; t < bar.tets.rows(); ++t)
    if (bar.rest(bar.tets(t, 0), 0) < 3.5) weights[static_cast<std::size_t>(t)] = 8;
  const std::vector<int> owner = partition_tets(bar.tets, weights, 2);
  std::array<double, 2> weight{0, 0};
  std::array<std::size_t, 2> count{0, 0};
  for (std::size_t t = 0; t < owner.size(); ++t) {
    weight[static_cast<std::size_t>(owner[t])] += weights[t];
    ++count[static_cast<std::size_t>(owner[t])];
  }
  const double total = weight[0] + weight[1];
  EXPECT_NEAR(weight[0], total / 2, 0.05 * total / 2);
  EXPECT_NEAR(weight[1], total / 2, 0.05 * total / 2);
  EXPECT_GT(std::max(count[0], count[1]), 2 * std::min(count[0], count[1])) << "the light part has far more tets";
}

TEST(PartitionTets, OnePartOrFewerTetsThanPartsNeedsNoPartitioner) {
  const mesh::TetMesh cube = testing::box_mesh(1, 1, 1, 1.0);  // 6 tets
  EXPECT_EQ(partition_tets(cube.tets, {}, 1), std::vector<int>(6, 0));
  EXPECT_EQ(partition_tets(cube.tets, {}, 8), (std::vector<int>{0, 1, 2, 3, 4, 5}));
  EXPECT_TRUE(partition_tets(Tets(0, 4), {}, 2).empty());
}

TEST(PartitionTets, WeightsOfTheWrongSizeOrBelowOneAreErrors) {
  const mesh::TetMesh bar = testing::box_mesh(4, 1, 1, 1.0);
  EXPECT_THAT([&] { partition_tets(bar.tets, std::vector<int>(5, 1), 2); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("5 weights for 24 tets")));
  std::vector<int> weights(24, 1);
  weights[7] = 0;
  EXPECT_THAT([&] { partition_tets(bar.tets, weights, 2); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("weight is below 1")));
}

TEST(NodeOwners, EachNodeGoesToTheOwnerOfTheFirstTetThatUsesIt) {
  Tets tets(2, 4);
  tets << 0, 1, 2, 3,  //
      1, 2, 3, 4;
  EXPECT_EQ(node_owners(tets, {1, 0}, 6), (std::vector<int>{1, 1, 1, 1, 0, 0}));
  EXPECT_THAT([&] { node_owners(tets, {0}, 6); }, ::testing::ThrowsMessage<Error>(::testing::HasSubstr("1 owners for 2 tets")));
  EXPECT_THAT([&] { node_owners(tets, {0, 0}, 4); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("refers to node 4 of 4")));
}

}  // namespace
}  // namespace sinew::parallel
