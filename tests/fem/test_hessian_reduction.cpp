#include <gtest/gtest.h>

#include <random>

#include "sinew/core/block_sparse_matrix.hpp"
#include "sinew/fem/dof_map.hpp"
#include "sinew/fem/hessian_reduction.hpp"
#include "support/problem_builder.hpp"

using namespace sinew;
namespace st = sinew::testing;

namespace {

/// A bar [0,3]x[0,1]x[0,1] with every kind of node: free, planar (the x = 0 face, two unknowns;
/// its edge z = 0, one), one prescribed node, and the members of a rigid region (tets with centroid x > 2).
fem::Problem bar_with_every_node_kind(fem::RigidBody::Kind rigid_kind) {
  auto p = st::box_problem(6, 2, 2, Vector3(0, 0, 0), Vector3(3, 1, 1), st::mooney_rivlin(), 1.0);
  st::add_rigid_region(p, "bone", rigid_kind, 3.0, [](const Vector3& c) { return c.x() > 2.0; });
  p.planar.push_back({"x0", st::nodes_on_plane(p.mesh, 0, 0.0), Vector3(1, 0, 0), 0.0, {}});
  std::vector<Index> edge;  // in two planes: one unknown each
  for (Index a : st::nodes_on_plane(p.mesh, 0, 0.0))
    if (p.mesh.rest(a, 2) == 0.0) edge.push_back(a);
  p.planar.push_back({"z0", edge, Vector3(0, 0, 1), 0.0, {}});
  p.prescribed.push_back({"pin", {1}, fem::RigidMotion{}});
  return p;
}

/// The tets' node pairs and, like contact pairs, random pairs of nodes anywhere in the mesh.
std::vector<std::pair<Index, Index>> tet_and_random_pairs(const fem::Problem& p, std::mt19937& rng) {
  std::vector<std::pair<Index, Index>> pairs;
  for (Index t = 0; t < p.mesh.tets.rows(); ++t)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) pairs.emplace_back(p.mesh.tets(t, i), p.mesh.tets(t, j));
  std::uniform_int_distribution<Index> node(0, p.mesh.num_nodes() - 1);
  for (int k = 0; k < 60; ++k) pairs.emplace_back(node(rng), node(rng));
  return pairs;
}

}  // namespace

class HessianReductionPattern : public ::testing::TestWithParam<fem::RigidBody::Kind> {};

// K = Jᵀ H J for random blocks in H, and K's pattern holds exactly the entries that can be
// nonzero (some are zero at this state: a rigid member on an axis through the body's centre does
// not move when the body turns about that axis), and the whole diagonal.
TEST_P(HessianReductionPattern, HoldsExactlyTheEntriesOfJtHJ) {
  const fem::Problem problem = bar_with_every_node_kind(GetParam());
  const fem::DofMap dofs(problem);
  const fem::State state = dofs.initial_state(0.5);
  std::mt19937 rng(7);
  BlockSparseMatrix H;
  H.set_pattern(problem.mesh.num_nodes(), tet_and_random_pairs(problem, rng));
  std::uniform_real_distribution<double> u(-1, 1);
  for (Index a = 0; a < H.num_nodes(); ++a)
    for (Index k = H.row_offsets()[a]; k < H.row_offsets()[a + 1]; ++k) {
      const Index b = H.columns()[k];
      if (b < a) continue;
      Matrix3 M;
      for (int i = 0; i < 9; ++i) M(i / 3, i % 3) = u(rng);
      if (a == b) M = (M + M.transpose()).eval();
      H.values()[static_cast<std::size_t>(k)] = M;
      H.values()[static_cast<std::size_t>(H.find(b, a))] = M.transpose();
    }

  fem::HessianReduction reduction(dofs);
  reduction.bind(H);
  fem::SparseMatrix K;
  reduction.reduce(state, H, NodalVectors::Zero(H.num_nodes(), 3), VectorX(), K);

  const Index n = dofs.num_dofs();
  MatrixX J = MatrixX::Zero(3 * H.num_nodes(), n);
  for (Index a = 0; a < H.num_nodes(); ++a)
    if (dofs.num_node_dofs(a) > 0) J.block(3 * a, dofs.first_dof(a), 3, dofs.num_node_dofs(a)) = dofs.node_jacobian(state, a);
  const MatrixX reference = J.transpose() * H.to_dense() * J;
  ASSERT_EQ(K.rows(), n);
  EXPECT_LT((MatrixX(K) - reference).norm(), 1e-12 * reference.norm());

  // The entries that can be nonzero: those of Sᵀ P S with P one on H's blocks and S one wherever
  // a node's position depends on an unknown (all nonnegative, so nothing cancels).
  MatrixX S = MatrixX::Zero(3 * H.num_nodes(), n);
  for (Index a = 0; a < H.num_nodes(); ++a)
    if (dofs.num_node_dofs(a) > 0) S.block(3 * a, dofs.first_dof(a), 3, dofs.num_node_dofs(a)).setOnes();
  MatrixX P = MatrixX::Zero(3 * H.num_nodes(), 3 * H.num_nodes());
  for (Index a = 0; a < H.num_nodes(); ++a)
    for (Index k = H.row_offsets()[a]; k < H.row_offsets()[a + 1]; ++k) P.block(3 * a, 3 * H.columns()[k], 3, 3).setOnes();
  const MatrixX structure = S.transpose() * P * S;
  Index expected_entries = 0;
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < n; ++j) expected_entries += structure(i, j) != 0 || i == j;
  EXPECT_EQ(K.nonZeros(), expected_entries);
  ASSERT_TRUE(K.isCompressed());
  for (Index c = 0; c < n; ++c)
    for (Index k = K.outerIndexPtr()[c] + 1; k < K.outerIndexPtr()[c + 1]; ++k)
      EXPECT_LT(K.innerIndexPtr()[k - 1], K.innerIndexPtr()[k]) << "column " << c << " is not strictly sorted";

  // A K of the same size and number of nonzeros but another pattern (another pattern's K of the
  // same count) takes the bound pattern; it does not keep its own.
  std::vector<Eigen::Triplet<double>> packed;
  for (Index k = 0; k < K.nonZeros(); ++k) packed.emplace_back(k % n, k / n, 1.0);
  fem::SparseMatrix other(n, n);
  other.setFromTriplets(packed.begin(), packed.end());
  ASSERT_EQ(other.nonZeros(), K.nonZeros());
  reduction.reduce(state, H, NodalVectors::Zero(H.num_nodes(), 3), VectorX(), other);
  EXPECT_EQ(MatrixX(other), MatrixX(K));
  EXPECT_TRUE(std::equal(K.innerIndexPtr(), K.innerIndexPtr() + K.nonZeros(), other.innerIndexPtr()));
}

INSTANTIATE_TEST_SUITE_P(RigidKinds, HessianReductionPattern,
                         ::testing::Values(fem::RigidBody::Kind::Free, fem::RigidBody::Kind::Prescribed));
