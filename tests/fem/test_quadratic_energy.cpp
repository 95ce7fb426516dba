/// @file test_quadratic_energy.cpp
/// The inertia / viscosity term E = (s/2)(x - c)ᵀ A (x - c): value, gradient and Hessian against
/// finite differences and the dense matrix; linear combinations of block matrices.

#include <gtest/gtest.h>

#include <random>

#include "sinew/fem/mass_matrix.hpp"
#include "sinew/fem/quadratic_energy.hpp"
#include "support/box_mesh.hpp"
#include "support/fd_check.hpp"

namespace sinew::fem {
namespace {

namespace st = sinew::testing;

BlockSparseMatrix box_mass(MassKind kind) {
  const mesh::TetMesh m = st::box_mesh(2, 1, 1, Vector3(0, 0, 0), Vector3(2, 1, 1));
  return block_mass_matrix(mass_matrix(m.rest, m.tets, m.region, std::vector<double>{3.0}, kind));
}

Positions random_positions(Index n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Positions x(n, 3);
  for (Index i = 0; i < x.size(); ++i) x.data()[i] = u(rng);
  return x;
}

TEST(QuadraticEnergy, GradientAndHessianMatchFiniteDifferencesAndTheDenseMatrix) {
  for (const MassKind kind : {MassKind::Lumped, MassKind::Consistent}) {
    const BlockSparseMatrix A = box_mass(kind);
    const Index n = A.num_nodes();
    QuadraticEnergy energy("inertia", A);
    const double scale = 1.0 / (0.01 * 0.01);
    energy.set_center_and_scale(random_positions(n, 1), scale);
    const Positions x = random_positions(n, 2);
    auto flat = [](const Positions& p) { return Eigen::VectorXd(p.reshaped<Eigen::RowMajor>()); };
    auto unflat = [n](const Eigen::VectorXd& v) { return Positions(v.reshaped<Eigen::RowMajor>(n, 3)); };
    NodalVectors g = NodalVectors::Zero(n, 3);
    energy.add_gradient(x, g);
    const Eigen::VectorXd fd = st::fd_gradient([&](const Eigen::VectorXd& v) { return energy.value(unflat(v)); },
                                               flat(x), 1e-6);
    EXPECT_LT((flat(g) - fd).norm(), 1e-6 * fd.norm());

    std::vector<std::pair<Index, Index>> pairs;
    energy.hessian_pattern(pairs);
    BlockSparseMatrix H;
    H.set_pattern(n, pairs);
    energy.bind_pattern(H);
    energy.add_hessian(x, H);
    EXPECT_LT((H.to_dense() - scale * A.to_dense()).norm(), 1e-12 * scale * A.to_dense().norm());
    // Kinetic energy of a rigid velocity: (1/2) m |v|².
    const NodalVectors v = NodalVectors::Ones(n, 3);
    EXPECT_NEAR(energy.quadratic_form(v), 0.5 * (2 * 3.0) * 3, 1e-12);
  }
}

TEST(QuadraticEnergy, ZeroScaleIsOffAndBadInputIsRejected) {
  const BlockSparseMatrix A = box_mass(MassKind::Lumped);
  QuadraticEnergy energy("viscosity", A);
  energy.set_center_and_scale(Positions::Zero(A.num_nodes(), 3), 0.0);
  EXPECT_EQ(energy.value(Positions::Ones(A.num_nodes(), 3)), 0.0);
  EXPECT_FALSE(energy.has_hessian());
  EXPECT_THROW(energy.set_center_and_scale(Positions::Zero(A.num_nodes() + 1, 3), 1.0), std::invalid_argument);
  EXPECT_THROW(energy.set_center_and_scale(Positions::Zero(A.num_nodes(), 3), -1.0), std::invalid_argument);
}

TEST(QuadraticEnergy, LinearCombinationAddsOnTheUnionOfThePatterns) {
  const BlockSparseMatrix lumped = box_mass(MassKind::Lumped), consistent = box_mass(MassKind::Consistent);
  const BlockSparseMatrix C = linear_combination(2.0, lumped, -0.5, consistent);
  EXPECT_LT((C.to_dense() - (2.0 * lumped.to_dense() - 0.5 * consistent.to_dense())).norm(), 1e-14);
  EXPECT_EQ(C.num_blocks(), consistent.num_blocks());
}

}  // namespace
}  // namespace sinew::fem
