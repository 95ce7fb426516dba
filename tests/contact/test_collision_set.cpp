// CollisionSet (src/sinew/contact/collision_set.hpp): the pairs it finds against a brute-force
// search over every (triangle, tet), a single known crossing, the Hessian pattern union and its
// revision, the candidate cap, and that updating to the same positions changes nothing.

#include "sinew/contact/collision_set.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

#include "sinew/collision/clip_triangle_tet.hpp"
#include "sinew/core/error.hpp"
#include "support/contact_fixtures.hpp"

namespace sinew::contact {
namespace {

namespace st = sinew::testing;

using PairSet = std::set<std::pair<Index, Index>>;

PairSet as_set(const std::vector<std::pair<Index, Index>>& pairs) { return {pairs.begin(), pairs.end()}; }

bool shares_node(const ContactGeometry& g, Index f, Index t) {
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 4; ++k)
      if (g.surface(f, i) == g.tets(t, k)) return true;
  return false;
}

/// Every (triangle, tet) with a penalty, a tet with depth, no shared node and contact by the
/// method's own test, found without any tree.
PairSet brute_force_pairs(const ContactGeometry& g, const Positions& x, ContactMethod method) {
  PairSet out;
  for (Index f = 0; f < g.surface.rows(); ++f)
    for (Index t = 0; t < g.tets.rows(); ++t) {
      if (pair_penalty(g, f, t) == 0 || shares_node(g, f, t)) continue;
      double depth = 0;
      for (int k = 0; k < 4; ++k) depth = std::max(depth, g.depth[g.tets(t, k)]);
      if (depth == 0) continue;
      const PairGeometry pg = pair_geometry(g, x, f, t);
      const bool hit =
          method == ContactMethod::Area
              ? tet_crosses_triangle_plane(pg) && collision::clip_triangle_tet(pg.triangle, pg.tet).count >= 3
              : collision::triangle_vertices_in_tet(pg.triangle, pg.tet).count > 0;
      if (hit) out.emplace(f, t);
    }
  return out;
}

class CollisionSetMethods : public ::testing::TestWithParam<ContactMethod> {};

TEST_P(CollisionSetMethods, FindsThePairsOfABruteForceSearch) {
  const auto boxes = st::two_boxes(2, Vector3(0.55, 0.3, -0.2), 0.4, 7.0, false);
  CollisionSet set(boxes.geometry, GetParam());
  set.update(boxes.x);
  ASSERT_FALSE(set.overflowed());
  const PairSet expected = brute_force_pairs(boxes.geometry, boxes.x, GetParam());
  ASSERT_GT(expected.size(), 10u);
  EXPECT_EQ(as_set(set.pair_indices()), expected);
  EXPECT_EQ(set.pair_indices().size(), expected.size());  // no duplicates
  for (const ActivePair& p : set.pairs()) EXPECT_EQ(p.penalty, 7.0);
  EXPECT_GE(set.times().candidates, static_cast<Index>(expected.size()));
}

TEST_P(CollisionSetMethods, RebuildFindsTheSamePairsAsUpdate) {
  const auto boxes = st::two_boxes(2, Vector3(0.5, 0.2, 0.1), 0.3, 7.0);
  const auto moved = st::two_boxes(2, Vector3(0.7, 0.1, 0.05), 0.3, 7.0);
  CollisionSet refit(boxes.geometry, GetParam());
  refit.update(boxes.x);
  refit.update(moved.x);  // tree refit from boxes.x
  CollisionSet rebuilt(boxes.geometry, GetParam());
  rebuilt.rebuild(moved.x);
  EXPECT_EQ(refit.pair_indices(), rebuilt.pair_indices());
  EXPECT_TRUE(refit.is_current(moved.x));
  EXPECT_FALSE(refit.is_current(boxes.x));
}

TEST_P(CollisionSetMethods, PatternRevisionGrowsOnlyWhenNewBlocksAppear) {
  const auto apart = st::two_boxes(2, Vector3(3, 0, 0), 0.3, 7.0);
  const auto shallow = st::two_boxes(2, Vector3(0.9, 0.1, 0.05), 0.3, 7.0);
  const auto deep = st::two_boxes(2, Vector3(0.5, 0.2, 0.1), 0.3, 7.0);
  CollisionSet set(apart.geometry, GetParam());
  EXPECT_EQ(set.pattern_revision(), 0u);
  set.rebuild(apart.x);
  EXPECT_TRUE(set.pairs().empty());
  EXPECT_EQ(set.pattern_revision(), 0u);
  EXPECT_EQ(set.pattern_size(), 0u);

  set.update(deep.x);
  ASSERT_FALSE(set.pairs().empty());
  EXPECT_EQ(set.pattern_revision(), 1u);
  const std::size_t deep_blocks = set.pattern_size();
  // Every off-diagonal block of every active pair is in the pattern, listed once as (a < b).
  std::vector<std::pair<Index, Index>> blocks;
  set.append_pattern(blocks);
  EXPECT_EQ(blocks.size(), deep_blocks);
  const PairSet listed = as_set(blocks);
  EXPECT_EQ(listed.size(), blocks.size());
  for (const ActivePair& p : set.pairs()) {
    const auto nodes = set.nodes(p);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      for (std::size_t j = i + 1; j < nodes.size(); ++j) {
        if (nodes[i] == nodes[j]) continue;
        EXPECT_TRUE(listed.count({std::min(nodes[i], nodes[j]), std::max(nodes[i], nodes[j])}))
            << nodes[i] << ", " << nodes[j];
      }
  }

  // Same positions, no contact, the same contact again: the union does not grow.
  set.update(deep.x);
  set.update(apart.x);
  EXPECT_TRUE(set.pairs().empty());
  set.update(deep.x);
  EXPECT_EQ(set.pattern_revision(), 1u);
  EXPECT_EQ(set.pattern_size(), deep_blocks);

  // A shallower overlap: revision + 1 exactly when it brings blocks the union lacks.
  set.update(shallow.x);
  ASSERT_FALSE(set.pairs().empty());
  const bool grew = set.pattern_size() > deep_blocks;
  EXPECT_EQ(set.pattern_revision(), grew ? 2u : 1u);
  const auto revision = set.pattern_revision();
  const std::size_t size = set.pattern_size();
  set.update(deep.x);
  set.update(shallow.x);
  EXPECT_EQ(set.pattern_revision(), revision);
  EXPECT_EQ(set.pattern_size(), size);
}

TEST_P(CollisionSetMethods, MoreCandidatesThanTheCapOverflowWithoutPairs) {
  const auto boxes = st::two_boxes(2, Vector3(0.62, 0.31, 0.17), 0.3, 7.0);
  CollisionSet roomy(boxes.geometry, GetParam());
  roomy.update(boxes.x);
  ASSERT_FALSE(roomy.overflowed());
  const auto candidates = static_cast<std::size_t>(roomy.times().candidates);
  ASSERT_GT(candidates, 20u);
  const auto tets = static_cast<std::size_t>(boxes.geometry.tets.rows());
  EXPECT_EQ(roomy.candidate_cap(), std::max<std::size_t>(100000, 20 * tets));  // automatic

  CollisionSet at_cap(boxes.geometry, GetParam(), candidates);
  at_cap.update(boxes.x);
  EXPECT_FALSE(at_cap.overflowed());
  EXPECT_EQ(at_cap.pair_indices(), roomy.pair_indices());

  CollisionSet capped(boxes.geometry, GetParam(), candidates - 1);
  capped.update(boxes.x);
  EXPECT_TRUE(capped.overflowed());
  EXPECT_TRUE(capped.pairs().empty());
  EXPECT_EQ(capped.times().candidates, static_cast<Index>(candidates));
  EXPECT_EQ(capped.pattern_revision(), 0u);  // an overflowed state adds nothing to the pattern
  EXPECT_EQ(capped.pattern_size(), 0u);
  // Apart, the same set is valid again.
  const auto apart = st::two_boxes(2, Vector3(3, 0, 0), 0.3, 7.0);
  capped.update(apart.x);
  EXPECT_FALSE(capped.overflowed());
}

TEST_P(CollisionSetMethods, PartsThatSplitTheTetsAndJoinTheirPairsFindTheWholeSetsPairs) {
  // Two parts in one process: part 1 keeps its own pairs (a join that gathers nothing), part 0
  // joins part 1's, as MPI's gather would on two ranks (docs/mpi.md).
  const auto boxes = st::two_boxes(2, Vector3(0.55, 0.3, -0.2), 0.4, 7.0, false);
  const auto moved = st::two_boxes(2, Vector3(0.7, 0.1, 0.05), 0.3, 7.0, false);
  const auto tets = static_cast<std::size_t>(boxes.geometry.tets.rows());
  CollisionShare part0, part1;
  part0.detects_tet.resize(tets);
  part1.detects_tet.resize(tets);
  for (std::size_t t = 0; t < tets; ++t) (t % 3 == 0 ? part1 : part0).detects_tet[t] = 1;
  std::vector<ActivePair> pairs_of_1;
  std::size_t candidates_of_1 = 0;
  part1.join = [&](std::vector<ActivePair>& pairs, std::size_t& candidates) {
    pairs_of_1 = pairs;
    candidates_of_1 = candidates;
  };
  part0.join = [&](std::vector<ActivePair>& pairs, std::size_t& candidates) {
    pairs.insert(pairs.end(), pairs_of_1.begin(), pairs_of_1.end());
    candidates += candidates_of_1;
  };
  CollisionSet whole(boxes.geometry, GetParam()), one(boxes.geometry, GetParam()), zero(boxes.geometry, GetParam());
  one.set_share(part1);
  zero.set_share(part0);
  for (const Positions* x : {&boxes.x, &moved.x}) {
    whole.update(*x);
    one.update(*x);
    zero.update(*x);
    ASSERT_GT(whole.pairs().size(), 10u);
    // Part 1 detected the pairs of its tets only, and part 0 ends with all of them.
    PairSet expected_of_1;
    for (const auto& [f, t] : whole.pair_indices())
      if (t % 3 == 0) expected_of_1.emplace(f, t);
    ASSERT_FALSE(expected_of_1.empty());
    EXPECT_EQ(as_set(one.pair_indices()), expected_of_1);
    EXPECT_EQ(as_set(zero.pair_indices()), as_set(whole.pair_indices()));
    EXPECT_EQ(zero.pairs().size(), whole.pairs().size());
    EXPECT_EQ(zero.times().candidates, whole.times().candidates);
    EXPECT_LT(one.times().candidates, whole.times().candidates);
    // Each pair's support is the whole set's (the same narrow phase of the same pair).
    for (const ActivePair& p : zero.pairs()) {
      const auto it = std::find_if(whole.pairs().begin(), whole.pairs().end(),
                                   [&](const ActivePair& w) { return w.triangle == p.triangle && w.tet == p.tet; });
      ASSERT_NE(it, whole.pairs().end());
      EXPECT_EQ(p.support.polygon.count, it->support.polygon.count);
      EXPECT_EQ(p.support.points.count, it->support.points.count);
      EXPECT_EQ(p.penalty, it->penalty);
    }
  }
  std::vector<std::pair<Index, Index>> joined, all;
  zero.append_pattern(joined);
  whole.append_pattern(all);
  EXPECT_EQ(as_set(joined), as_set(all));
  EXPECT_EQ(zero.pattern_revision(), whole.pattern_revision());

  // Back to one part: detection is whole again.
  zero.set_share({});
  zero.update(boxes.x);
  whole.update(boxes.x);
  EXPECT_EQ(zero.pair_indices(), whole.pair_indices());
}

TEST_P(CollisionSetMethods, PartsThatTogetherPassTheCapOverflowOnEveryPart) {
  const auto boxes = st::two_boxes(2, Vector3(0.62, 0.31, 0.17), 0.3, 7.0);
  CollisionSet roomy(boxes.geometry, GetParam());
  roomy.update(boxes.x);
  const auto candidates = static_cast<std::size_t>(roomy.times().candidates);
  // A part whose own candidates are under the cap, joined with another's that bring the sum
  // over it: no pairs, overflowed, nothing added to the pattern.
  CollisionShare half;
  half.detects_tet.resize(static_cast<std::size_t>(boxes.geometry.tets.rows()));
  for (std::size_t t = 0; t < half.detects_tet.size(); t += 2) half.detects_tet[t] = 1;
  half.join = [&](std::vector<ActivePair>&, std::size_t& count) { count += candidates; };
  CollisionSet part(boxes.geometry, GetParam(), candidates);
  part.set_share(half);
  part.update(boxes.x);
  EXPECT_TRUE(part.overflowed());
  EXPECT_TRUE(part.pairs().empty());
  EXPECT_GT(part.times().candidates, static_cast<Index>(candidates));
  EXPECT_EQ(part.pattern_size(), 0u);
}

TEST(CollisionSet, RejectsAShareOfTheWrongSizeOrWithoutAJoin) {
  const auto boxes = st::two_boxes(2, Vector3(0.5, 0.2, 0.1), 0.3, 7.0);
  CollisionSet set(boxes.geometry, ContactMethod::Area);
  CollisionShare wrong;
  wrong.detects_tet.assign(3, 1);
  wrong.join = [](std::vector<ActivePair>&, std::size_t&) {};
  EXPECT_THROW(
      {
        try {
          set.set_share(wrong);
        } catch (const Error& e) {
          EXPECT_NE(std::string(e.what()).find("3 tet flags for"), std::string::npos) << e.what();
          throw;
        }
      },
      Error);
  CollisionShare no_join;
  no_join.detects_tet.assign(static_cast<std::size_t>(boxes.geometry.tets.rows()), 1);
  EXPECT_THROW(set.set_share(no_join), Error);
}

INSTANTIATE_TEST_SUITE_P(Methods, CollisionSetMethods, ::testing::Values(ContactMethod::Area, ContactMethod::Point),
                         [](const auto& info) { return info.param == ContactMethod::Area ? "Area" : "Point"; });

/// One tet (body 0, depth 1 at its apex) pierced by one triangle (body 1) through its middle.
struct Crossing {
  ContactGeometry geometry;
  Positions x;
};

Crossing crossing() {
  Crossing c;
  c.x.resize(7, 3);
  c.x << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1,  // tet
      -0.5, -0.5, 0.2, 2, -0.5, 0.2, -0.5, 2, 0.2;  // triangle in the plane z = 0.2, normal +z
  auto& g = c.geometry;
  g.tets.resize(1, 4);
  g.tets << 0, 1, 2, 3;
  g.tet_body.setZero(1);
  g.surface.resize(1, 3);
  g.surface << 4, 5, 6;
  g.surface_body.setOnes(1);
  g.depth = VectorX::Zero(7);
  g.depth[3] = 1;
  g.penalty = MatrixX::Constant(2, 2, 5.0);
  return c;
}

TEST(CollisionSet, OneTrianglePiercingOneTetIsOnePair) {
  const Crossing c = crossing();
  CollisionSet area(c.geometry, ContactMethod::Area);
  area.update(c.x);
  ASSERT_EQ(area.pair_indices(), (std::vector<std::pair<Index, Index>>{{0, 0}}));
  const ActivePair& p = area.pairs().front();
  EXPECT_EQ(p.penalty, 5.0);
  EXPECT_GE(p.support.polygon.count, 3);  // the tet's cross-section at z = 0.2, a triangle
  EXPECT_EQ(area.nodes(p), (std::array<Index, 7>{4, 5, 6, 0, 1, 2, 3}));
  const PolygonMoments m = area.integrator().moments(area.pair_geometry_at(c.x, p), p.support);
  EXPECT_NEAR(m.area, 0.5 * 0.8 * 0.8, 1e-14);
  EXPECT_NEAR(m.max_depth, 0.2, 1e-14);
  // No triangle vertex lies in the tet: point collocation has no pair.
  CollisionSet point(c.geometry, ContactMethod::Point);
  point.update(c.x);
  EXPECT_TRUE(point.pairs().empty());
  EXPECT_EQ(point.method(), ContactMethod::Point);
  EXPECT_EQ(area.method(), ContactMethod::Area);
}

TEST(CollisionSet, ZeroDepthTetsAndZeroPenaltiesMakeNoPairs) {
  Crossing c = crossing();
  ContactGeometry no_depth = c.geometry;
  no_depth.depth.setZero();
  CollisionSet flat(no_depth, ContactMethod::Area);
  flat.update(c.x);
  EXPECT_TRUE(flat.pairs().empty());
  ContactGeometry off = c.geometry;
  off.penalty(0, 1) = off.penalty(1, 0) = 0;
  CollisionSet none(off, ContactMethod::Area);
  none.update(c.x);
  EXPECT_TRUE(none.pairs().empty());
}

TEST(CollisionSet, UpdatingToTheSamePositionsKeepsEverything) {
  const auto boxes = st::two_boxes(2, Vector3(0.5, 0.2, 0.1), 0.3, 7.0);
  CollisionSet set(boxes.geometry, ContactMethod::Area);
  EXPECT_FALSE(set.is_current(boxes.x));
  EXPECT_EQ(set.positions().rows(), 0);
  set.update(boxes.x);
  const ActivePair* first = set.pairs().data();
  const auto pairs = set.pair_indices();
  set.update(Positions(boxes.x));
  EXPECT_EQ(set.pairs().data(), first);  // not recomputed
  EXPECT_EQ(set.pair_indices(), pairs);
  EXPECT_TRUE(set.is_current(boxes.x));
}

TEST(CollisionSet, RejectsInvalidGeometryAndPositions) {
  const Crossing c = crossing();
  ContactGeometry bad = c.geometry;
  bad.depth[2] = -1;
  EXPECT_THROW(CollisionSet(bad, ContactMethod::Area), InputError);
  CollisionSet set(c.geometry, ContactMethod::Area);
  EXPECT_THROW(set.update(Positions::Zero(6, 3)), std::invalid_argument);
  EXPECT_THROW(set.rebuild(Positions::Zero(8, 3)), std::invalid_argument);
  // Two sets can share one geometry.
  CollisionSet other(set.shared_geometry(), ContactMethod::Point);
  EXPECT_EQ(&other.geometry(), &set.geometry());
}

}  // namespace
}  // namespace sinew::contact
