/// @file test_rigid_body_modes.cpp
/// fem::rigid_body_modes: the q-space images of the six rigid motions, which PETSc's GAMG takes as
/// its near-null space. On an unconstrained body (free nodes and a free rigid region) at rest
/// they are the tangent's null space; under planar constraints they stay an orthonormal basis.

#include "sinew/fem/rigid_body_modes.hpp"

#include <gtest/gtest.h>

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

}  // namespace
