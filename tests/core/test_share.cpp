/// @file test_share.cpp
/// share_of: the parts of a list of work items.

#include <gtest/gtest.h>

#include <algorithm>

#include "sinew/core/share.hpp"

namespace sinew {
namespace {

TEST(Share, PartsCoverTheItemsInContiguousPiecesThatDifferByAtMostOne) {
  for (std::size_t count : {0u, 1u, 5u, 17u, 1000u}) {
    for (int parts : {1, 2, 3, 4, 7}) {
      std::size_t next = 0, smallest = count + 1, largest = 0;
      for (int part = 0; part < parts; ++part) {
        const ItemRange range = share_of(count, part, parts);
        EXPECT_EQ(range.begin, next) << count << " items, part " << part << " of " << parts;
        EXPECT_LE(range.begin, range.end);
        smallest = std::min(smallest, range.end - range.begin);
        largest = std::max(largest, range.end - range.begin);
        next = range.end;
      }
      EXPECT_EQ(next, count) << count << " items in " << parts;
      EXPECT_LE(largest - smallest, 1u) << count << " items in " << parts;
    }
  }
  // 10 items in 4 parts: 3, 3, 2, 2.
  EXPECT_EQ(share_of(10, 1, 4).begin, 3u);
  EXPECT_EQ(share_of(10, 1, 4).end, 6u);
  EXPECT_EQ(share_of(10, 3, 4).begin, 8u);
  // No parts is one part.
  EXPECT_EQ(share_of(10, 0, 0).end, 10u);
}

}  // namespace
}  // namespace sinew
