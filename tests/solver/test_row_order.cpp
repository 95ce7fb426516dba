/// @file test_row_order.cpp
/// Which rows of the Newton matrix each MPI rank holds in a shared linear solve: the unknowns of
/// its nodes, renumbered rank by rank in whole blocks; a rigid body's unknowns on rank 0.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numeric>

#include "sinew/core/error.hpp"
#include "sinew/fem/dof_map.hpp"
#include "sinew/solver/row_order.hpp"
#include "support/problem_builder.hpp"

namespace sinew::solver {
namespace {

namespace st = sinew::testing;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(OrderRowsByOwner, GathersEachRanksBlocksInTheirOrder) {
  const RowOrder order = order_rows_by_owner(12, {1, 1, 1, 0, 0, 0, 1, 1, 1, 0, 0, 0}, 2, 3);
  EXPECT_THAT(order.first, ElementsAre(0, 6, 12));
  EXPECT_THAT(order.old_of_new, ElementsAre(3, 4, 5, 9, 10, 11, 0, 1, 2, 6, 7, 8));
}

TEST(OrderRowsByOwner, AWholeBlockFollowsItsFirstUnknown) {
  const RowOrder order = order_rows_by_owner(6, {2, 0, 0, 0, 2, 2}, 3, 3);
  EXPECT_THAT(order.first, ElementsAre(0, 3, 3, 6));  // rank 1 holds no rows
  EXPECT_THAT(order.old_of_new, ElementsAre(3, 4, 5, 0, 1, 2));
}

TEST(OrderRowsByOwner, WithoutOwnersTheRanksTakeContiguousSharesOfBlocks) {
  const RowOrder order = order_rows_by_owner(9, {}, 2, 3);
  EXPECT_THAT(order.first, ElementsAre(0, 6, 9));
  std::vector<Index> identity(9);
  std::iota(identity.begin(), identity.end(), Index{0});
  EXPECT_EQ(order.old_of_new, identity);
  EXPECT_THAT(order_rows_by_owner(5, {}, 2, 1).first, ElementsAre(0, 3, 5));
}

TEST(OrderRowsByOwner, BadOwnersAreErrors) {
  EXPECT_THAT([] { order_rows_by_owner(6, {0, 0, 0}, 2, 3); }, ::testing::ThrowsMessage<Error>(HasSubstr("3 owners for 6 unknowns")));
  EXPECT_THAT([] { order_rows_by_owner(3, {0, 2, 0}, 2, 1); }, ::testing::ThrowsMessage<Error>(HasSubstr("owned by rank 2 of 2")));
  EXPECT_THAT([] { order_rows_by_owner(3, {0, -1, 0}, 2, 1); }, ::testing::ThrowsMessage<Error>(HasSubstr("rank -1")));
  EXPECT_THAT([] { order_rows_by_owner(7, {}, 2, 3); }, ::testing::ThrowsMessage<Error>(HasSubstr("not blocks of 3")));
}

TEST(UnknownOwners, ANodesUnknownsGoToItsOwnerARigidBodysToRankZero) {
  auto problem = st::box_problem(2, 1, 1, Vector3(0, 0, 0), Vector3(2, 1, 1), st::mooney_rivlin(), 1.0);
  st::add_rigid_region(problem, "bone", fem::RigidBody::Kind::Free, 3.0, [](const Vector3& c) { return c.x() > 1.0; });
  const fem::DofMap dofs(problem);
  const Index nodes = problem.mesh.num_nodes();
  std::vector<int> node_owner(static_cast<std::size_t>(nodes));
  for (Index a = 0; a < nodes; ++a) node_owner[static_cast<std::size_t>(a)] = 1 + static_cast<int>(a % 2);

  const std::vector<int> owner = unknown_owners(dofs, node_owner, nodes);
  ASSERT_EQ(owner.size(), static_cast<std::size_t>(dofs.num_dofs()));
  ASSERT_EQ(dofs.num_rigid_bodies(), 1U);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(owner[static_cast<std::size_t>(dofs.rigid_first_dof(0) + k)], 0);
  int free_nodes = 0;
  for (Index a = 0; a < nodes; ++a) {
    if (dofs.kind(a) != fem::DofMap::NodeKind::Free) continue;
    ++free_nodes;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(owner[static_cast<std::size_t>(dofs.first_dof(a) + k)], 1 + a % 2) << a;
  }
  EXPECT_GT(free_nodes, 0);
  EXPECT_TRUE(unknown_owners(dofs, {}, nodes).empty());
  EXPECT_THAT([&] { unknown_owners(dofs, {0, 1}, nodes); }, ::testing::ThrowsMessage<Error>(HasSubstr("2 node owners")));
}

}  // namespace
}  // namespace sinew::solver
