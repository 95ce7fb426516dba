/// @file test_pair_unknowns.cpp
/// Pair Hessians with respect to one side only (pair_integral.hpp, PairUnknowns): the rows of the
/// side that varies are the same numbers as those of the full 21 x 21 Hessian, the held side's are
/// zero; pair_unknowns() picks the side from the immovable nodes; and a contact energy whose
/// geometry marks one body immovable gives the same Hessian on the other body's nodes.

#include <gtest/gtest.h>

#include <random>

#include "pair_integral_support.hpp"
#include "sinew/contact/contact_energy.hpp"
#include "support/contact_fixtures.hpp"

namespace sinew::contact {
namespace {

namespace st = sinew::testing;
using pair_testing::random_method_pair;

/// The Hessian and gradient with respect to `unknowns` by method.
pair_testing::Derivatives one_side(const PairGeometry& pg, bool area, PairUnknowns unknowns) {
  pair_testing::Derivatives d;
  if (area)
    d.value = area_integral_hessian(pg, collision::clip_triangle_tet(pg.triangle, pg.tet), PairHessian::Exact,
                                    d.gradient, d.hessian, unknowns);
  else
    d.value = point_integral_hessian(pg, collision::triangle_vertices_in_tet(pg.triangle, pg.tet),
                                     PairHessian::Exact, d.gradient, d.hessian, unknowns);
  return d;
}

void expect_rows_of_one_side(bool area, bool with_multiplier) {
  std::mt19937 rng(area ? 41 : 43);
  for (int trial = 0; trial < 40; ++trial) {
    PairGeometry pg = random_method_pair(rng, area, trial);
    if (with_multiplier) pg.multiplier = Vector3(0.3, 0.0, 0.7);
    const auto all = pair_testing::pair_hessian(pg, area, PairHessian::Exact);
    for (const PairUnknowns unknowns : {PairUnknowns::Triangle, PairUnknowns::Tet}) {
      const int first = unknowns == PairUnknowns::Triangle ? 0 : 9;
      const int count = unknowns == PairUnknowns::Triangle ? 9 : 12;
      const auto side = one_side(pg, area, unknowns);
      EXPECT_EQ(side.value, all.value);
      for (int i = 0; i < kPairVariables; ++i) {
        const bool varies_i = i >= first && i < first + count;
        if (varies_i)
          EXPECT_NEAR(side.gradient[i], all.gradient[i], 1e-14 * (1 + all.gradient.cwiseAbs().maxCoeff()));
        else
          EXPECT_EQ(side.gradient[i], 0.0);
        for (int j = 0; j < kPairVariables; ++j) {
          const bool varies_j = j >= first && j < first + count;
          if (varies_i && varies_j)
            EXPECT_NEAR(side.hessian(i, j), all.hessian(i, j), 1e-13 * (1 + all.hessian.cwiseAbs().maxCoeff()))
                << "trial " << trial << " entry " << i << ", " << j;
          else
            EXPECT_EQ(side.hessian(i, j), 0.0) << "trial " << trial << " entry " << i << ", " << j;
        }
      }
    }
  }
}

TEST(PairUnknowns, AreaHessianOfOneSideIsThatSideOfTheFullHessian) { expect_rows_of_one_side(true, false); }
TEST(PairUnknowns, PointHessianOfOneSideIsThatSideOfTheFullHessian) { expect_rows_of_one_side(false, false); }
TEST(PairUnknowns, WithMultipliersToo) {
  expect_rows_of_one_side(true, true);
  expect_rows_of_one_side(false, true);
}

TEST(PairUnknowns, ProjectedHessianIgnoresThemAndKeepsAllRows) {
  std::mt19937 rng(47);
  const PairGeometry pg = pair_testing::random_pair(rng);
  const auto polygon = collision::clip_triangle_tet(pg.triangle, pg.tet);
  PairVector g_all, g_tet;
  PairMatrix h_all, h_tet;
  area_integral_hessian(pg, polygon, PairHessian::Projected, g_all, h_all);
  area_integral_hessian(pg, polygon, PairHessian::Projected, g_tet, h_tet, PairUnknowns::Tet);
  EXPECT_EQ(h_tet, h_all);
  EXPECT_EQ(g_tet, g_all);
}

TEST(PairUnknowns, PickTheSideWhoseNodesMove) {
  auto boxes = st::two_boxes(2, Vector3(0.8, 0.0, 0.0), 0.0, 7.0, false);
  ContactGeometry& g = boxes.geometry;
  const Index f = 0, t = g.tets.rows() - 1;  // a triangle of body 0, a tet of body 1
  ASSERT_EQ(g.surface_body[f], 0);
  ASSERT_EQ(g.tet_body[t], 1);
  EXPECT_EQ(pair_unknowns(g, f, t), PairUnknowns::All);  // no mask
  std::vector<std::uint8_t> immovable(static_cast<std::size_t>(boxes.x.rows()), 0);
  for (Index a = 0; a < boxes.x.rows() / 2; ++a) immovable[static_cast<std::size_t>(a)] = 1;  // body 0 held
  g.node_immovable = immovable;
  EXPECT_EQ(pair_unknowns(g, f, t), PairUnknowns::Tet);
  EXPECT_EQ(pair_unknowns(g, g.surface.rows() - 1, 0), PairUnknowns::Triangle);  // body 1's triangle, body 0's tet
  g.node_immovable[static_cast<std::size_t>(g.surface(f, 1))] = 0;  // one node of the triangle moves
  EXPECT_EQ(pair_unknowns(g, f, t), PairUnknowns::All);
  g.node_immovable.assign(static_cast<std::size_t>(boxes.x.rows()), 1);  // both held
  EXPECT_EQ(pair_unknowns(g, f, t), PairUnknowns::All);
}

TEST(PairUnknowns, ContactHessianOnTheNodesThatMoveIsUnchangedByTheMask) {
  auto boxes = st::two_boxes(2, Vector3(0.8, 0.0, 0.0), 0.0, 7.0, false);
  const Index nodes = boxes.x.rows();
  ContactEnergy free_energy(boxes.geometry, {ContactMethod::Area, PairHessian::Exact});
  ContactGeometry held_geometry = boxes.geometry;
  held_geometry.node_immovable.assign(static_cast<std::size_t>(nodes), 0);
  for (Index a = 0; a < nodes / 2; ++a) held_geometry.node_immovable[static_cast<std::size_t>(a)] = 1;
  ContactEnergy held_energy(held_geometry, {ContactMethod::Area, PairHessian::Exact});
  free_energy.update(boxes.x);
  held_energy.update(boxes.x);
  ASSERT_EQ(held_energy.collisions().pairs().size(), free_energy.collisions().pairs().size());

  const auto hessian_of = [&](const ContactEnergy& energy) {
    std::vector<std::pair<Index, Index>> pattern;
    energy.hessian_pattern(pattern);
    BlockSparseMatrix H;
    H.set_pattern(nodes, pattern);
    energy.add_hessian(boxes.x, H);
    return H;
  };
  const BlockSparseMatrix free_H = hessian_of(free_energy), held_H = hessian_of(held_energy);
  double largest = 0;
  for (const Matrix3& block : free_H.values()) largest = std::max(largest, block.cwiseAbs().maxCoeff());
  ASSERT_GT(largest, 0);
  int compared = 0;
  for (Index a = nodes / 2; a < nodes; ++a)
    for (Index b = nodes / 2; b < nodes; ++b) {
      const Index k = free_H.find(a, b);
      if (k < 0) continue;
      ASSERT_EQ(held_H.find(a, b), k);
      EXPECT_LE((held_H.values()[k] - free_H.values()[k]).cwiseAbs().maxCoeff(), 1e-13 * largest)
          << "block " << a << ", " << b;
      ++compared;
    }
  EXPECT_GT(compared, 0);
}

}  // namespace
}  // namespace sinew::contact
