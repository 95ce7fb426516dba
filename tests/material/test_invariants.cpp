/// @file test_invariants.cpp
/// Closed-form invariants of C = F^T F and their derivatives against finite differences.

#include "sinew/material/invariants.hpp"

#include <gtest/gtest.h>

#include <functional>

#include "random_deformation.hpp"
#include "support/fd_check.hpp"

namespace sinew::material {
namespace {

using sinew::testing::fd_gradient;
using sinew::testing::fd_jacobian;
using sinew::testing::relative_error;
using test_support::random_deformation;

constexpr double kStep = 1e-6;
constexpr double kTolerance = 1e-7;

Matrix3 as_matrix(const Eigen::VectorXd& x) { return unvec(Vector9(x)); }

/// Checks a scalar function of F and its closed-form gradient and Hessian by central differences.
void check_derivatives(const std::function<double(const Matrix3&)>& value,
                       const std::function<Vector9(const Matrix3&)>& gradient,
                       const std::function<Matrix9(const Matrix3&)>& hessian, const Matrix3& F) {
  const Eigen::VectorXd x = vec(F);
  const Eigen::VectorXd fd_g =
      fd_gradient([&](const Eigen::VectorXd& y) { return value(as_matrix(y)); }, x, kStep);
  EXPECT_LT(relative_error(gradient(F), fd_g), kTolerance) << "F =\n" << F;
  const Eigen::MatrixXd fd_h = fd_jacobian(
      [&](const Eigen::VectorXd& y) -> Eigen::VectorXd { return gradient(as_matrix(y)); }, x, kStep);
  const Matrix9 H = hessian(F);
  EXPECT_LT(relative_error(H, fd_h), kTolerance) << "F =\n" << F;
  EXPECT_LT((H - H.transpose()).norm(), 1e-12 * H.norm());
}

TEST(Invariants, ValuesMatchDefinitions) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 5; ++trial) {
    const Matrix3 F = random_deformation(rng);
    const Matrix3 C = F.transpose() * F;
    const Invariants inv = compute_invariants(F);
    EXPECT_NEAR(inv.I1, C.trace(), 1e-13);
    EXPECT_NEAR(inv.I2, 0.5 * (C.trace() * C.trace() - (C * C).trace()), 1e-12);
    // I2 is also the trace of cof C.
    EXPECT_NEAR(inv.I2, cofactor(C).trace(), 1e-12);
    EXPECT_NEAR(inv.J, F.determinant(), 1e-13);
    EXPECT_NEAR(inv.J * inv.J, C.determinant(), 1e-12);
  }
  const Invariants rest = compute_invariants(Matrix3::Identity());
  EXPECT_DOUBLE_EQ(rest.I1, 3.0);
  EXPECT_DOUBLE_EQ(rest.I2, 3.0);
  EXPECT_DOUBLE_EQ(rest.J, 1.0);
}

TEST(Invariants, CofactorIsDetTimesInverseTranspose) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 5; ++trial) {
    const Matrix3 F = random_deformation(rng);
    const Matrix3 expected = F.determinant() * F.inverse().transpose();
    EXPECT_LT((cofactor(F) - expected).norm(), 1e-13 * expected.norm());
  }
  // Well defined for a singular F: rank-2 F has a rank-1 cofactor, not zero.
  Matrix3 singular = Matrix3::Identity();
  singular(0, 0) = 0.0;
  Matrix3 expected = Matrix3::Zero();
  expected(0, 0) = 1.0;
  EXPECT_EQ(cofactor(singular), expected);
}

TEST(Invariants, VecIsColumnMajor) {
  Matrix3 A;
  A << 1, 2, 3, 4, 5, 6, 7, 8, 9;
  const Vector9 v = vec(A);
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) EXPECT_EQ(v[i + 3 * j], A(i, j));
  }
  EXPECT_EQ(unvec(v), A);
}

TEST(Invariants, DerivativesMatchFiniteDifferences) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 4; ++trial) {
    const Matrix3 F = random_deformation(rng);
    SCOPED_TRACE(trial);
    check_derivatives([](const Matrix3& G) { return compute_invariants(G).I1; }, d_I1_dF,
                      [](const Matrix3&) { return d2_I1_dF2(); }, F);
    check_derivatives([](const Matrix3& G) { return compute_invariants(G).I2; }, d_I2_dF, d2_I2_dF2, F);
    check_derivatives([](const Matrix3& G) { return G.determinant(); }, d_J_dF, d2_J_dF2, F);
    check_derivatives([](const Matrix3& G) { return (G.transpose() * G).determinant(); }, d_I3_dF,
                      d2_I3_dF2, F);
  }
}

TEST(Invariants, ChainRuleMatchesFiniteDifferencesOfAGenericEnergy) {
  // psi = I1^2 I2 / 7 + sin(J) I1 + J^3 I2: every gradient and Hessian entry non-zero.
  const auto energy_of = [](const Invariants& inv) {
    InvariantEnergy e;
    const double I1 = inv.I1, I2 = inv.I2, J = inv.J;
    e.psi = I1 * I1 * I2 / 7.0 + std::sin(J) * I1 + J * J * J * I2;
    e.gradient = Vector3(2.0 * I1 * I2 / 7.0 + std::sin(J), I1 * I1 / 7.0 + J * J * J,
                         std::cos(J) * I1 + 3.0 * J * J * I2);
    e.hessian << 2.0 * I2 / 7.0, 2.0 * I1 / 7.0, std::cos(J),  //
        2.0 * I1 / 7.0, 0.0, 3.0 * J * J,                        //
        std::cos(J), 3.0 * J * J, -std::sin(J) * I1 + 6.0 * J * I2;
    return e;
  };
  const auto psi = [&](const Matrix3& F) { return evaluate_invariant_law(F, energy_of, nullptr, nullptr); };
  const auto P = [&](const Matrix3& F) {
    Matrix3 stress;
    evaluate_invariant_law(F, energy_of, &stress, nullptr);
    return vec(stress);
  };
  const auto dPdF = [&](const Matrix3& F) {
    Matrix9 tangent;
    evaluate_invariant_law(F, energy_of, nullptr, &tangent);
    return tangent;
  };
  std::mt19937 rng(5);
  for (int trial = 0; trial < 4; ++trial) check_derivatives(psi, P, dPdF, random_deformation(rng));
}

}  // namespace
}  // namespace sinew::material
