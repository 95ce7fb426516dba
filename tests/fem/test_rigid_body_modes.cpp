/// @file test_rigid_body_modes.cpp
/// fem::rigid_body_modes: the q-space images of the six rigid motions, which PETSc's GAMG takes as
/// its near-null space. On an unconstrained body (free nodes and a free rigid region) at rest
/// they are the tangent's null space; under planar constraints they stay an orthonormal basis.

#include "sinew/fem/rigid_body_modes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "sinew/fem/elastic_energy.hpp"
#include "sinew/fem/hessian_reduction.hpp"
#include "support/problem_builder.hpp"

using namespace sinew;
namespace st = sinew::testing;

namespace {

/// A box [0,2]x[0,1]x[0,1] whose tets with centroid x > 1.5 form a free rigid body; nothing held.
fem::Problem floating_problem() {
  auto p = st::box_problem(4, 2, 2, Vector3(0, 0, 0), Vector3(2, 1, 1), st::mooney_rivlin(), 1.0);
  st::add_rigid_region(p, "bone", fem::RigidBody::Kind::Free, 3.0, [](const Vector3& c) { return c.x() > 1.5; });
  return p;
}

/// The q-space tangent of the elastic energy at `state`.
fem::SparseMatrix tangent(const fem::Problem& problem, const fem::DofMap& dofs, const fem::State& state) {
  fem::ElasticEnergy elastic(problem.mesh.rest, problem.mesh.tets, st::tet_materials(problem));
  std::vector<std::pair<Index, Index>> pairs;
  elastic.hessian_pattern(pairs);
  BlockSparseMatrix H;
  H.set_pattern(problem.mesh.num_nodes(), pairs);
  elastic.bind_pattern(H);
  fem::HessianReduction reduction(dofs);
  reduction.bind(H);
  elastic.add_hessian(state.x, H);
  NodalVectors g = NodalVectors::Zero(state.x.rows(), 3);
  elastic.add_gradient(state.x, g);
  fem::SparseMatrix K;
  reduction.reduce(state, H, g, VectorX(), K);
  return K;
}

TEST(RigidBodyModes, AreTheNullSpaceOfAFloatingBodysTangentAtRest) {
  const fem::Problem problem = floating_problem();
  const fem::DofMap dofs(problem);
  const fem::State rest = dofs.initial_state(0);
  const MatrixX modes = fem::rigid_body_modes(dofs, rest);
  ASSERT_EQ(modes.rows(), dofs.num_dofs());
  ASSERT_EQ(modes.cols(), 6);
  EXPECT_LT((modes.transpose() * modes - MatrixX::Identity(6, 6)).norm(), 1e-12);
  const fem::SparseMatrix K = tangent(problem, dofs, rest);
  const double scale = MatrixX(K).norm();
  EXPECT_LT((K * modes).norm(), 1e-10 * scale);
  // A deformation that is not rigid is not in the span (the check above is not vacuous).
  VectorX stretch = VectorX::Zero(dofs.num_dofs());
  for (Index a = 0; a < rest.x.rows(); ++a)
    if (dofs.kind(a) == fem::DofMap::NodeKind::Free) stretch[dofs.first_dof(a)] = rest.x(a, 0);
  EXPECT_GT((K * stretch).norm(), 1e-3 * scale * stretch.norm());
  EXPECT_EQ(fem::unknowns_block_size(dofs, rest.x.rows()), 3);
}

TEST(RigidBodyModes, StayOrthonormalUnderPlanarConstraintsWithBlockSizeOne) {
  fem::Problem problem = floating_problem();
  problem.planar.push_back({"x0", st::nodes_on_plane(problem.mesh, 0, 0.0), Vector3(1, 0, 0), 0.0, {}});
  const fem::DofMap dofs(problem);
  const fem::State rest = dofs.initial_state(0);
  const MatrixX modes = fem::rigid_body_modes(dofs, rest);
  ASSERT_EQ(modes.rows(), dofs.num_dofs());
  ASSERT_EQ(modes.cols(), 6);  // the in-plane parts of all six motions remain independent
  EXPECT_LT((modes.transpose() * modes - MatrixX::Identity(6, 6)).norm(), 1e-12);
  EXPECT_EQ(fem::unknowns_block_size(dofs, rest.x.rows()), 1);
  // The motions the plane allows (y, z translation, rotation about x) are still null vectors.
  const fem::SparseMatrix K = tangent(problem, dofs, rest);
  const double scale = MatrixX(K).norm();
  VectorX along_y = VectorX::Zero(dofs.num_dofs());
  for (Index a = 0; a < rest.x.rows(); ++a) {
    const auto J = dofs.node_jacobian(rest, a);
    if (J.cols() == 0) continue;
    if (dofs.kind(a) == fem::DofMap::NodeKind::RigidMember)
      along_y.segment<6>(dofs.first_dof(a)) << 0, 1, 0, 0, 0, 0;  // the body's translation
    else
      along_y.segment(dofs.first_dof(a), J.cols()) = J.transpose() * Vector3::UnitY();  // orthonormal basis
  }
  EXPECT_LT((K * along_y).norm(), 1e-10 * scale * along_y.norm());
  const VectorX projected = modes * (modes.transpose() * along_y);
  EXPECT_LT((projected - along_y).norm(), 1e-10 * along_y.norm());
}

// On several MPI ranks each fits the rows it holds, and a Gram matrix summed over them (twice)
// makes the rows one orthonormal basis (solver::rigid_body_modes_of_rows). Two interleaved sets of
// rows stand for two ranks here: they give the fit of all rows, and a basis of the same span as
// the QR of one process.
TEST(RigidBodyModes, RowsFittedApartAndJoinedByTheirSummedGramMatrixSpanTheModes) {
  fem::Problem problem = floating_problem();
  problem.planar.push_back({"x0", st::nodes_on_plane(problem.mesh, 0, 0.0), Vector3(1, 0, 0), 0.0, {}});
  const fem::DofMap dofs(problem);
  const fem::State rest = dofs.initial_state(0);
  const Index n = dofs.num_dofs();
  std::vector<Index> every(static_cast<std::size_t>(n)), rank[2];
  for (Index q = 0; q < n; ++q) {
    every[static_cast<std::size_t>(q)] = q;
    rank[(q / 7) % 2].push_back(q);  // runs of 7 rows, like a partition cutting a rigid body's six
  }
  const MatrixX whole = fem::rigid_body_motions(dofs, rest, every);
  MatrixX part[2] = {fem::rigid_body_motions(dofs, rest, rank[0]), fem::rigid_body_motions(dofs, rest, rank[1])};
  for (int r = 0; r < 2; ++r)
    for (std::size_t i = 0; i < rank[r].size(); ++i)
      EXPECT_EQ(part[r].row(static_cast<Index>(i)), whole.row(rank[r][i])) << "unknown " << rank[r][i];

  for (int round = 0; round < 2; ++round) {
    const MatrixX gram = part[0].transpose() * part[0] + part[1].transpose() * part[1];
    const MatrixX T = fem::orthonormalizing_transform(gram);
    ASSERT_EQ(T.cols(), 6);
    for (auto& p : part) p = p * T;
  }
  MatrixX joined(n, 6);
  for (int r = 0; r < 2; ++r)
    for (std::size_t i = 0; i < rank[r].size(); ++i) joined.row(rank[r][i]) = part[r].row(static_cast<Index>(i));
  EXPECT_LT((joined.transpose() * joined - MatrixX::Identity(6, 6)).norm(), 1e-13);
  const MatrixX modes = fem::rigid_body_modes(dofs, rest);
  EXPECT_LT((modes - joined * (joined.transpose() * modes)).norm(), 1e-12);  // the same span
  EXPECT_LT((joined - modes * (modes.transpose() * joined)).norm(), 1e-12);

  // A direction the rows do not span is left out, and a Gram matrix that is not finite gives none.
  MatrixX gram = MatrixX::Zero(3, 3);
  gram.diagonal() << 4.0, 0.0, 1e-20;
  const MatrixX T = fem::orthonormalizing_transform(gram);
  ASSERT_EQ(T.cols(), 1);
  EXPECT_NEAR(std::abs(T(0, 0)), 0.5, 1e-15);
  gram(1, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(fem::orthonormalizing_transform(gram).cols(), 0);
}

}  // namespace
