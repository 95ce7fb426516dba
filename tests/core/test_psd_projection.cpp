/// @file test_psd_projection.cpp
/// Projection onto the positive semi-definite cone.

#include "sinew/core/psd_projection.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>
#include <stdexcept>

namespace sinew {
namespace {

/// A random symmetric N x N matrix Q diag(values) Q^T with the given eigenvalues.
template <int N>
Eigen::Matrix<double, N, N> with_eigenvalues(const Eigen::Matrix<double, N, 1>& values, std::mt19937& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Matrix<double, N, N> G;
  for (int k = 0; k < N * N; ++k) G.data()[k] = normal(rng);
  const Eigen::HouseholderQR<Eigen::Matrix<double, N, N>> qr(G);
  const Eigen::Matrix<double, N, N> Q = qr.householderQ();
  return Q * values.asDiagonal() * Q.transpose();
}

template <class Matrix>
double min_eigenvalue(const Matrix& A) {
  return Eigen::SelfAdjointEigenSolver<Matrix>(A).eigenvalues().minCoeff();
}

TEST(PsdProjection, IndefiniteMatrixBecomesNearestPsd) {
  std::mt19937 rng(1);
  Vector9 values;
  values << -3.0, -1.0, -0.2, 0.0, 0.5, 1.0, 2.0, 4.0, 8.0;
  const Matrix9 A = with_eigenvalues<9>(values, rng);
  ASSERT_LT(min_eigenvalue(A), -2.9);

  const Matrix9 projected = project_to_psd(A);
  EXPECT_LT((projected - projected.transpose()).norm(), 1e-14 * projected.norm());
  EXPECT_GE(min_eigenvalue(projected), -1e-12 * A.norm());
  // The eigenvalues are the clamped ones.
  Vector9 expected_values = values.cwiseMax(0.0);
  Vector9 got_values = Eigen::SelfAdjointEigenSolver<Matrix9>(projected).eigenvalues();
  EXPECT_LT((got_values - expected_values).norm(), 1e-12 * A.norm());
  // A = A+ + A- with A- negative semi-definite and A+ A- = 0 (orthogonal parts).
  const Matrix9 negative_part = A - projected;
  EXPECT_LE(Eigen::SelfAdjointEigenSolver<Matrix9>(negative_part).eigenvalues().maxCoeff(), 1e-12 * A.norm());
  EXPECT_LT((projected * negative_part).norm(), 1e-12 * A.squaredNorm());
}

TEST(PsdProjection, PsdMatrixIsUnchanged) {
  std::mt19937 rng(2);
  Vector9 definite;
  definite << 0.1, 0.5, 1.0, 1.0, 2.0, 3.0, 5.0, 8.0, 13.0;
  const Matrix9 A = with_eigenvalues<9>(definite, rng);
  const Matrix9 A_symmetric = 0.5 * (A + A.transpose());
  EXPECT_EQ(project_to_psd(A_symmetric), A_symmetric);

  Vector9 semi_definite = definite;
  semi_definite[0] = 0.0;
  semi_definite[1] = 0.0;
  const Matrix9 B = with_eigenvalues<9>(semi_definite, rng);
  EXPECT_LT((project_to_psd(B) - B).norm(), 1e-12 * B.norm());

  const Matrix9 zero = Matrix9::Zero();
  EXPECT_EQ(project_to_psd(zero), zero);
}

TEST(PsdProjection, NegativeDefiniteMatrixBecomesZero) {
  std::mt19937 rng(3);
  Vector9 values = -Vector9::LinSpaced(1.0, 9.0);
  EXPECT_LT(project_to_psd(with_eigenvalues<9>(values, rng)).norm(), 1e-12);
}

TEST(PsdProjection, NonSymmetricInputIsSymmetrizedFirst) {
  Matrix9 A = Matrix9::Identity();
  A(0, 1) = 1.0;  // symmetric part has 0.5 off the diagonal, still positive definite
  Matrix9 expected = Matrix9::Identity();
  expected(0, 1) = expected(1, 0) = 0.5;
  EXPECT_EQ(project_to_psd(A), expected);
}

TEST(PsdProjection, TwelveByTwelveAndDynamicSizes) {
  std::mt19937 rng(4);
  Eigen::Matrix<double, 12, 1> values = Eigen::Matrix<double, 12, 1>::LinSpaced(-5.0, 6.0);
  const Matrix12 A = with_eigenvalues<12>(values, rng);
  const Matrix12 projected = project_to_psd(A);
  EXPECT_GE(min_eigenvalue(projected), -1e-12 * A.norm());
  EXPECT_GT(projected.norm(), 1.0);

  MatrixX dynamic = A;
  project_to_psd_in_place(dynamic);
  EXPECT_LT((dynamic - projected).norm(), 1e-12 * A.norm());

  // In place on a block of a larger matrix.
  MatrixX big = MatrixX::Zero(14, 14);
  big.block(1, 1, 12, 12) = A;
  project_to_psd_in_place(big.block(1, 1, 12, 12));
  EXPECT_LT((big.block(1, 1, 12, 12) - projected).norm(), 1e-12 * A.norm());
  EXPECT_EQ(big.row(0).norm(), 0.0);

  MatrixX not_square(3, 4);
  EXPECT_THROW(project_to_psd_in_place(not_square), std::invalid_argument);
}

}  // namespace
}  // namespace sinew
