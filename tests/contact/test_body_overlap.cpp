// Immovable pairs (contact_geometry.hpp, node_immovable) and body_overlaps (body_overlap.hpp):
// contact leaves out a (triangle, tet) pair only when all 7 of its nodes are immovable, and the
// overlap report finds the overlap of two bodies with its depth and place, whether contact
// takes those pairs or leaves them out.

#include "sinew/contact/body_overlap.hpp"

#include <gtest/gtest.h>

#include "sinew/contact/collision_set.hpp"
#include "sinew/contact/contact_energy.hpp"
#include "sinew/contact/contact_report.hpp"
#include "sinew/core/error.hpp"
#include "support/contact_fixtures.hpp"

namespace sinew::contact {
namespace {

namespace st = sinew::testing;

/// Two unit boxes of 2^3 cubes, the second shifted by 0.8 in x: they overlap in a 0.2-thick slab.
st::TwoBoxes boxes_overlapping_in_a_slab() { return st::two_boxes(2, Vector3(0.8, 0.0, 0.0), 0.0, 7.0, false); }

/// 1 for the nodes of body 0 (the first half of the nodes), `other` for those of body 1.
std::vector<std::uint8_t> first_body_immovable(Index nodes, std::uint8_t other) {
  std::vector<std::uint8_t> immovable(static_cast<std::size_t>(nodes), other);
  for (Index a = 0; a < nodes / 2; ++a) immovable[static_cast<std::size_t>(a)] = 1;
  return immovable;
}

TEST(ImmovablePairs, ArePairsWhoseSevenNodesAreAllImmovable) {
  auto boxes = boxes_overlapping_in_a_slab();
  ContactGeometry& g = boxes.geometry;
  g.node_immovable = first_body_immovable(boxes.x.rows(), 0);
  for (Index f = 0; f < g.surface.rows(); ++f) EXPECT_FALSE(pair_is_immovable(g, f, g.tets.rows() - 1));
  g.node_immovable.assign(static_cast<std::size_t>(boxes.x.rows()), 1);
  EXPECT_TRUE(pair_is_immovable(g, 0, g.tets.rows() - 1));
  g.node_immovable[static_cast<std::size_t>(g.tets(g.tets.rows() - 1, 2))] = 0;  // one node of the tet moves
  EXPECT_FALSE(pair_is_immovable(g, 0, g.tets.rows() - 1));
  g.node_immovable.clear();
  EXPECT_FALSE(pair_is_immovable(g, 0, 0));
}

TEST(ImmovablePairs, ContactLeavesOutOnlyPairsOfTwoImmovableSides) {
  auto boxes = boxes_overlapping_in_a_slab();
  ContactGeometry& g = boxes.geometry;
  CollisionSet every(g, ContactMethod::Area);
  every.update(boxes.x);
  ASSERT_GT(every.pairs().size(), 0u);

  g.node_immovable = first_body_immovable(boxes.x.rows(), 0);  // body 0 fixed, body 1 free
  CollisionSet one_side(g, ContactMethod::Area);
  one_side.update(boxes.x);
  EXPECT_EQ(one_side.pairs().size(), every.pairs().size());

  g.node_immovable = first_body_immovable(boxes.x.rows(), 1);  // both fixed
  ContactEnergy energy(g, {ContactMethod::Area, PairHessian::Exact});
  energy.update(boxes.x);
  EXPECT_EQ(energy.value(boxes.x), 0.0);
  const ContactReport report = contact_report(energy, boxes.x);
  EXPECT_EQ(report.pairs, 0);
  EXPECT_EQ(report.max_penetration, 0.0);
}

TEST(ImmovablePairs, AMaskOfTheWrongSizeIsRefused) {
  auto boxes = boxes_overlapping_in_a_slab();
  boxes.geometry.node_immovable.assign(3, 1);
  try {
    validate_contact_geometry(boxes.geometry);
    FAIL() << "a node_immovable of 3 entries was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("node_immovable has 3 entries for"), std::string::npos) << e.what();
  }
}

TEST(BodyOverlaps, FindTheDeepestOverlapAndItsPlace) {
  auto boxes = boxes_overlapping_in_a_slab();
  const auto overlaps = body_overlaps(boxes.geometry, boxes.x, ContactMethod::Area, 0.0);
  ASSERT_EQ(overlaps.size(), 1u);
  const BodyOverlap& o = overlaps.front();
  EXPECT_EQ(o.body_a, 0);
  EXPECT_EQ(o.body_b, 1);
  EXPECT_FALSE(o.immovable);
  EXPECT_GT(o.pairs, 0);
  // The slab 0.8 <= x <= 1 is 0.2 deep from either box's face.
  EXPECT_GT(o.max_depth, 0.1);
  EXPECT_LE(o.max_depth, 0.2 + 1e-12);
  EXPECT_GE(o.place.x(), 0.8 - 1e-12);
  EXPECT_LE(o.place.x(), 1.0 + 1e-12);
  // Same figures as the contact report of the same pairs.
  const ContactReport report = contact_report(ContactEnergy(boxes.geometry, {}), boxes.x);
  EXPECT_DOUBLE_EQ(o.max_depth, report.max_penetration_between(0, 1));
}

TEST(BodyOverlaps, ReportImmovablePairsApartFromThoseContactTakes) {
  auto boxes = boxes_overlapping_in_a_slab();
  boxes.geometry.node_immovable = first_body_immovable(boxes.x.rows(), 1);
  const auto fixed = body_overlaps(boxes.geometry, boxes.x, ContactMethod::Area, 0.0);
  ASSERT_EQ(fixed.size(), 1u);
  EXPECT_TRUE(fixed.front().immovable);
  EXPECT_GT(fixed.front().max_depth, 0.1);

  // Free the nodes of body 1 at x > 1.2 (none of them in the slab): pairs with one of them
  // in a tet stay in contact; the others, fixed on both sides, are left out.
  for (Index a = boxes.x.rows() / 2; a < boxes.x.rows(); ++a)
    if (boxes.x(a, 0) > 1.2) boxes.geometry.node_immovable[static_cast<std::size_t>(a)] = 0;
  const auto mixed = body_overlaps(boxes.geometry, boxes.x, ContactMethod::Area, 0.0);
  ASSERT_EQ(mixed.size(), 2u);
  EXPECT_NE(mixed[0].immovable, mixed[1].immovable);
  EXPECT_GE(mixed[0].max_depth, mixed[1].max_depth);  // deepest first
  EXPECT_EQ(mixed[0].pairs + mixed[1].pairs, fixed.front().pairs);
}

TEST(BodyOverlaps, ShallowerThanTheThresholdAreNotReported) {
  const auto boxes = boxes_overlapping_in_a_slab();
  EXPECT_TRUE(body_overlaps(boxes.geometry, boxes.x, ContactMethod::Area, 0.25).empty());
  const auto apart = st::two_boxes(2, Vector3(1.5, 0.0, 0.0), 0.0, 7.0, false);
  EXPECT_TRUE(body_overlaps(apart.geometry, apart.x, ContactMethod::Area, 0.0).empty());
}

}  // namespace
}  // namespace sinew::contact
