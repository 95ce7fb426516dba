/// @file test_block_sparse_matrix.cpp
/// BlockSparseMatrix's pattern: the given node pairs made symmetric, every diagonal block added,
/// duplicates removed, rows sorted; find() locates every block and nothing else.

#include "sinew/core/block_sparse_matrix.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace sinew {
namespace {

TEST(BlockSparseMatrix, PatternIsTheSymmetricDeduplicatedPairsPlusTheDiagonal) {
  std::mt19937 rng(3);
  const Index nodes = 40;
  std::uniform_int_distribution<Index> node(0, nodes - 1);
  std::vector<std::pair<Index, Index>> pairs;
  for (int k = 0; k < 300; ++k) pairs.emplace_back(node(rng), node(rng));  // repeats, both orders, a == b
  std::set<std::pair<Index, Index>> expected;
  for (const auto& [a, b] : pairs) {
    expected.emplace(a, b);
    expected.emplace(b, a);
  }
  for (Index a = 0; a < nodes; ++a) expected.emplace(a, a);

  BlockSparseMatrix H;
  const auto version = H.pattern_version();
  H.set_pattern(nodes, pairs);
  EXPECT_GT(H.pattern_version(), version);
  ASSERT_EQ(H.num_blocks(), static_cast<Index>(expected.size()));
  ASSERT_EQ(H.row_offsets().size(), static_cast<std::size_t>(nodes) + 1);
  std::vector<std::pair<Index, Index>> listed;
  for (Index a = 0; a < nodes; ++a)
    for (Index k = H.row_offsets()[a]; k < H.row_offsets()[a + 1]; ++k) listed.emplace_back(a, H.columns()[k]);
  EXPECT_TRUE(std::equal(listed.begin(), listed.end(), expected.begin(), expected.end()));  // sorted, unique
  for (Index a = 0; a < nodes; ++a)
    for (Index b = 0; b < nodes; ++b) {
      const Index k = H.find(a, b);
      if (expected.count({a, b})) {
        ASSERT_GE(k, 0);
        EXPECT_EQ(H.columns()[k], b);
        EXPECT_EQ(H.values()[static_cast<std::size_t>(k)], Matrix3::Zero());
      } else {
        EXPECT_EQ(k, -1);
      }
    }
}

// New contact pairs only add blocks: set_pattern then says where each old block went, so that
// consumers rebind without searching; a pattern that drops a block says nothing.
TEST(BlockSparseMatrix, AGrownPatternMapsEveryOldBlockToItsNewPlace) {
  std::mt19937 rng(5);
  const Index nodes = 30;
  std::uniform_int_distribution<Index> node(0, nodes - 1);
  std::vector<std::pair<Index, Index>> pairs;
  for (int k = 0; k < 80; ++k) pairs.emplace_back(node(rng), node(rng));
  BlockSparseMatrix H, other;
  H.set_pattern(nodes, pairs);
  EXPECT_TRUE(H.moved_block_index().empty());  // no pattern before the first
  EXPECT_EQ(H.previous_pattern_version(), 0u);
  const std::vector<Index> old_offsets = H.row_offsets(), old_columns = H.columns();
  const auto old_version = H.pattern_version();
  other.set_pattern(nodes, pairs);
  EXPECT_NE(other.pattern_version(), old_version);  // no two patterns share a version

  std::vector<std::pair<Index, Index>> grown = pairs;
  for (int k = 0; k < 40; ++k) grown.emplace_back(node(rng), node(rng));
  H.set_pattern(nodes, grown);
  EXPECT_EQ(H.previous_pattern_version(), old_version);
  ASSERT_EQ(H.moved_block_index().size(), old_columns.size());
  EXPECT_GT(H.num_blocks(), static_cast<Index>(old_columns.size()));
  for (Index a = 0; a < nodes; ++a)
    for (Index k = old_offsets[a]; k < old_offsets[a + 1]; ++k)
      EXPECT_EQ(H.moved_block_index()[static_cast<std::size_t>(k)], H.find(a, old_columns[k]));

  H.set_pattern(nodes, pairs);  // drops the added blocks
  EXPECT_TRUE(H.moved_block_index().empty());
  H.set_pattern(nodes + 1, grown);  // another size
  EXPECT_TRUE(H.moved_block_index().empty());
}

TEST(BlockSparseMatrix, NoPairsGiveTheDiagonalOnly) {
  BlockSparseMatrix H;
  H.set_pattern(5, {});
  EXPECT_EQ(H.num_blocks(), 5);
  for (Index a = 0; a < 5; ++a) {
    EXPECT_EQ(H.find(a, a), a);
    EXPECT_EQ(H.find(a, (a + 1) % 5), -1);
  }
}

}  // namespace
}  // namespace sinew
