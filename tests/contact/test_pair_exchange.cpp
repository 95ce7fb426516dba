// Contact pairs as bytes (src/sinew/contact/pair_exchange.hpp): what the ranks of a run exchange
// comes back as the same pairs, for both methods, and truncated bytes are refused.

#include "sinew/contact/pair_exchange.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "support/contact_fixtures.hpp"

namespace sinew::contact {
namespace {

namespace st = sinew::testing;

void expect_same_pair(const ActivePair& a, const ActivePair& b, ContactMethod method) {
  EXPECT_EQ(a.triangle, b.triangle);
  EXPECT_EQ(a.tet, b.tet);
  EXPECT_EQ(a.penalty, b.penalty);
  if (method == ContactMethod::Area) {
    const auto& p = a.support.polygon;
    const auto& q = b.support.polygon;
    ASSERT_EQ(p.count, q.count);
    for (std::size_t k = 0; k < static_cast<std::size_t>(p.count); ++k) {
      EXPECT_EQ(p.vertices[k], q.vertices[k]);
      EXPECT_EQ(p.barycentric[k], q.barycentric[k]);
      EXPECT_EQ(p.provenance[k], q.provenance[k]);
    }
  } else {
    const auto& p = a.support.points;
    const auto& q = b.support.points;
    ASSERT_EQ(p.count, q.count);
    EXPECT_EQ(p.vertex, q.vertex);
    for (std::size_t k = 0; k < static_cast<std::size_t>(p.count); ++k) EXPECT_EQ(p.barycentric[k], q.barycentric[k]);
  }
}

class PairExchange : public ::testing::TestWithParam<ContactMethod> {};

TEST_P(PairExchange, PackedPairsUnpackToTheSamePairsAndTheSameEnergy) {
  const auto boxes = st::two_boxes(2, Vector3(0.55, 0.3, -0.2), 0.4, 7.0);
  CollisionSet set(boxes.geometry, GetParam());
  set.update(boxes.x);
  const std::vector<ActivePair>& pairs = set.pairs();
  ASSERT_GT(pairs.size(), 10u);
  // Two parts' bytes, concatenated as a gather would: the first half, then the rest.
  const std::vector<ActivePair> first(pairs.begin(), pairs.begin() + static_cast<long>(pairs.size() / 2));
  const std::vector<ActivePair> rest(pairs.begin() + static_cast<long>(pairs.size() / 2), pairs.end());
  std::vector<char> bytes;
  pack_pairs(first, GetParam(), bytes);
  pack_pairs(rest, GetParam(), bytes);
  const std::vector<ActivePair> back = unpack_pairs(bytes, GetParam());
  ASSERT_EQ(back.size(), pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) expect_same_pair(back[k], pairs[k], GetParam());
  // The integrals read from the unpacked supports are the same numbers.
  for (std::size_t k = 0; k < pairs.size(); ++k)
    EXPECT_EQ(set.integrator().integral(set.pair_geometry_at(boxes.x, back[k]), back[k].support),
              set.integrator().integral(set.pair_geometry_at(boxes.x, pairs[k]), pairs[k].support));
  // Only what the method uses is written: fewer bytes than the pairs' memory.
  EXPECT_LT(bytes.size(), pairs.size() * sizeof(ActivePair));

  EXPECT_TRUE(unpack_pairs({}, GetParam()).empty());
  std::vector<char> cut(bytes.begin(), bytes.end() - 3);
  EXPECT_THROW(unpack_pairs(cut, GetParam()), std::runtime_error);
}

INSTANTIATE_TEST_SUITE_P(Methods, PairExchange, ::testing::Values(ContactMethod::Area, ContactMethod::Point),
                         [](const auto& info) { return info.param == ContactMethod::Area ? "Area" : "Point"; });

}  // namespace
}  // namespace sinew::contact
