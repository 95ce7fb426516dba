/// @file test_laws.cpp
/// Properties every law must have (GUIDE.md section 3), for each base law with and without
/// the fiber term: derivatives against finite differences, stress-free rest, frame
/// invariance, blow-up as J -> 0+, +inf for det F <= 0, symmetric tangent, small-strain moduli.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "random_deformation.hpp"
#include "sinew/material/composite.hpp"
#include "sinew/material/fiber_reinforcement.hpp"
#include "sinew/material/invariants.hpp"
#include "sinew/material/material_spec.hpp"
#include "support/fd_check.hpp"

namespace sinew::material {
namespace {

using sinew::testing::fd_gradient;
using sinew::testing::fd_jacobian;
using sinew::testing::relative_error;
using test_support::random_deformation;
using test_support::random_rotation;

constexpr double kInfiniteEnergy = std::numeric_limits<double>::infinity();

struct LawCase {
  std::string label;
  MaterialSpec spec;
};

/// gtest prints the label instead of the bytes of a failing case's parameter.
void PrintTo(const LawCase& law_case, std::ostream* os) { *os << law_case.label; }

FiberParams test_fiber() {
  FiberParams fiber;
  fiber.alpha = 0.5;
  fiber.beta = 2.0;
  fiber.direction = Vector3(1.0, 2.0, -0.5);  // not unit: the factory normalizes it
  return fiber;
}

std::vector<LawCase> all_cases() {
  const MooneyRivlinParams mr{1.3, 0.4, 2.1};
  const VerondaWestmannParams vw{0.8, 1.2, 1.5};
  const NeoHookeanParams nh{1.1, 3.0};
  std::vector<LawCase> cases;
  for (const bool with_fiber : {false, true}) {
    const std::string suffix = with_fiber ? "WithFiber" : "";
    std::optional<FiberParams> fiber;
    if (with_fiber) fiber = test_fiber();
    cases.push_back({"MooneyRivlin" + suffix, MaterialSpec{mr, fiber}});
    cases.push_back({"VerondaWestmann" + suffix, MaterialSpec{vw, fiber}});
    cases.push_back({"NeoHookean" + suffix, MaterialSpec{nh, fiber}});
  }
  return cases;
}

class LawTest : public ::testing::TestWithParam<LawCase> {
 protected:
  void SetUp() override { material_ = make_material(GetParam().spec); }

  bool has_fiber() const { return GetParam().spec.fiber.has_value(); }
  Vector3 fiber_direction() const { return GetParam().spec.fiber->direction.normalized(); }

  /// A modulus scale for absolute tolerances (stress units).
  double modulus() const { return material_->initial_shear_modulus(); }

  double psi(const Matrix3& F) const { return material_->energy_density(F); }
  Matrix3 P(const Matrix3& F) const { return material_->first_piola(F); }
  Matrix9 dPdF(const Matrix3& F) const { return material_->first_piola_derivative(F); }

  MaterialPtr material_;
};

TEST_P(LawTest, StressMatchesFiniteDifferenceOfEnergy) {
  std::mt19937 rng(101);
  for (int trial = 0; trial < 6; ++trial) {
    const Matrix3 F = random_deformation(rng);
    const Eigen::VectorXd fd = fd_gradient(
        [&](const Eigen::VectorXd& x) { return psi(unvec(Vector9(x))); }, vec(F), 1e-6);
    EXPECT_LT(relative_error(vec(P(F)), fd), 1e-6) << "det F = " << F.determinant();
  }
}

TEST_P(LawTest, TangentMatchesFiniteDifferenceOfStress) {
  std::mt19937 rng(202);
  for (int trial = 0; trial < 6; ++trial) {
    const Matrix3 F = random_deformation(rng);
    const Eigen::MatrixXd fd = fd_jacobian(
        [&](const Eigen::VectorXd& x) -> Eigen::VectorXd { return vec(P(unvec(Vector9(x)))); }, vec(F),
        1e-6);
    EXPECT_LT(relative_error(dPdF(F), fd), 1e-6) << "det F = " << F.determinant();
  }
}

TEST_P(LawTest, TangentIsSymmetric) {
  std::mt19937 rng(303);
  for (int trial = 0; trial < 6; ++trial) {
    const Matrix9 A = dPdF(random_deformation(rng));
    EXPECT_LT((A - A.transpose()).norm(), 1e-13 * A.norm());
  }
}

TEST_P(LawTest, OutputsAreConsistentWhicheverAreRequested) {
  std::mt19937 rng(404);
  const Matrix3 F = random_deformation(rng);
  Matrix3 P_full;
  Matrix9 dPdF_full;
  const double psi_full = material_->evaluate(F, &P_full, &dPdF_full);
  Matrix3 P_only;
  Matrix9 dPdF_only;
  EXPECT_EQ(material_->evaluate(F, &P_only, nullptr), psi_full);
  EXPECT_EQ(material_->evaluate(F, nullptr, &dPdF_only), psi_full);
  EXPECT_EQ(material_->evaluate(F, nullptr, nullptr), psi_full);
  EXPECT_EQ(P_only, P_full);
  EXPECT_EQ(dPdF_only, dPdF_full);
}

TEST_P(LawTest, RestStateHasZeroEnergyAndZeroStress) {
  const Matrix3 I = Matrix3::Identity();
  Matrix3 stress;
  Matrix9 tangent;
  const double energy = material_->evaluate(I, &stress, &tangent);
  EXPECT_NEAR(energy, 0.0, 1e-14 * modulus());
  EXPECT_LE(stress.norm(), 1e-12 * modulus()) << stress;
  // Away from rest the energy is positive and the stress is not zero (the checks above are
  // not passing for a law that is identically zero).
  Matrix3 F = I;
  F(0, 1) = 0.1;
  EXPECT_GT(psi(F), 1e-4 * modulus());
  EXPECT_GT(P(F).norm(), 1e-2 * modulus());
}

TEST_P(LawTest, FrameInvariance) {
  std::mt19937 rng(505);
  for (int trial = 0; trial < 6; ++trial) {
    const Matrix3 F = random_deformation(rng);
    const Matrix3 Q = random_rotation(rng);
    ASSERT_NEAR(Q.determinant(), 1.0, 1e-12);
    const double psi_F = psi(F);
    EXPECT_NEAR(psi(Q * F), psi_F, 1e-12 * std::max(1.0, std::abs(psi_F)));
    const Matrix3 P_F = P(F);
    EXPECT_LT((P(Q * F) - Q * P_F).norm(), 1e-12 * P_F.norm());
    // dP(QF)/dF = (Id3 (x) Q) dPdF(F) (Id3 (x) Q)^T in the vec convention.
    Matrix9 block_Q = Matrix9::Zero();
    for (int b = 0; b < 3; ++b) block_Q.block<3, 3>(3 * b, 3 * b) = Q;
    const Matrix9 rotated = block_Q * dPdF(F) * block_Q.transpose();
    EXPECT_LT((dPdF(Q * F) - rotated).norm(), 1e-12 * rotated.norm());
  }
}

TEST_P(LawTest, IsotropicBaseIsInvariantUnderRestRotations) {
  // psi(F R) = psi(F) for rest rotations R only without a fiber, or with R about the fiber.
  std::mt19937 rng(606);
  const Matrix3 F = random_deformation(rng);
  Matrix3 R;
  if (has_fiber()) {
    R = Eigen::AngleAxisd(0.7, fiber_direction()).toRotationMatrix();
    // A rotation that moves the fiber changes the energy.
    const Matrix3 tilt = Eigen::AngleAxisd(0.7, fiber_direction().unitOrthogonal()).toRotationMatrix();
    EXPECT_GT(std::abs(psi(F * tilt) - psi(F)), 1e-6 * modulus());
  } else {
    R = random_rotation(rng);
  }
  EXPECT_NEAR(psi(F * R), psi(F), 1e-12 * std::max(1.0, std::abs(psi(F))));
}

TEST_P(LawTest, EnergyBlowsUpAsVolumeVanishes) {
  double previous = psi(Matrix3::Identity());
  double s = 1.0;
  for (int k = 0; k < 40; ++k) {
    s *= 0.5;
    const double current = psi(Vector3(s, 1.0, 1.0).asDiagonal());
    ASSERT_TRUE(std::isfinite(current)) << "s = " << s;
    EXPECT_GT(current, previous) << "s = " << s;
    previous = current;
  }
  // Logarithmic growth: at s = 1e-100 the energy exceeds 100 times the shear modulus.
  EXPECT_GT(psi(Vector3(1e-100, 1.0, 1.0).asDiagonal()), 100.0 * modulus());
}

TEST_P(LawTest, NonPositiveDeterminantGivesInfinityAndLeavesOutputsAlone) {
  std::mt19937 rng(707);
  Matrix3 reflection = Matrix3::Identity();
  reflection(2, 2) = -1.0;
  const std::vector<Matrix3> rejected = {
      Vector3(0.0, 1.0, 1.0).asDiagonal(),          // det F = 0
      Vector3(-1.0, 1.0, 1.0).asDiagonal(),         // a reflection
      Vector3(-0.5, -0.5, -0.5).asDiagonal(),       // point inversion
      reflection * random_deformation(rng),         // an inverted general F
      Matrix3::Zero(),
  };
  for (const Matrix3& F : rejected) {
    ASSERT_LE(F.determinant(), 0.0);
    Matrix3 stress = Matrix3::Constant(42.0);
    Matrix9 tangent = Matrix9::Constant(-7.0);
    EXPECT_EQ(material_->evaluate(F, &stress, &tangent), kInfiniteEnergy) << F;
    EXPECT_EQ(stress, Matrix3::Constant(42.0));
    EXPECT_EQ(tangent, Matrix9::Constant(-7.0));
    EXPECT_EQ(psi(F), kInfiniteEnergy);
  }
}

TEST_P(LawTest, SmallStrainModuliMatchTangentAtRest) {
  const double mu = material_->initial_shear_modulus();
  const double kappa = material_->initial_bulk_modulus();
  EXPECT_GT(mu, 0.0);
  EXPECT_GT(kappa, 0.0);
  // Isotropic linear elasticity: dP_ij/dF_kl = mu (d_ik d_jl + d_il d_jk) + (kappa - 2 mu/3) d_ij d_kl.
  Matrix9 expected = Matrix9::Zero();
  const auto delta = [](int p, int q) { return p == q ? 1.0 : 0.0; };
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          expected(i + 3 * j, k + 3 * l) = mu * (delta(i, k) * delta(j, l) + delta(i, l) * delta(j, k)) +
                                           (kappa - 2.0 * mu / 3.0) * delta(i, j) * delta(k, l);
  if (has_fiber()) {
    // The fiber adds 4 alpha beta^2 vec(d d^T) vec(d d^T)^T: stiffness along d only.
    const Vector3 d = fiber_direction();
    const Matrix3 ddT = d * d.transpose();
    expected += fiber_initial_axial_modulus(*GetParam().spec.fiber) * vec(ddT) * vec(ddT).transpose();
  }
  EXPECT_LT((dPdF(Matrix3::Identity()) - expected).norm(), 1e-12 * expected.norm())
      << "got\n" << dPdF(Matrix3::Identity()) << "\nexpected\n" << expected;
}

INSTANTIATE_TEST_SUITE_P(AllLaws, LawTest, ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<LawCase>& info) { return info.param.label; });

TEST(CompositeMaterial, ReportsTheBaseModuliAndName) {
  const MooneyRivlinParams mr{1.3, 0.4, 2.1};
  const MaterialPtr base = make_material(MaterialSpec{mr, std::nullopt});
  const MaterialPtr composite = make_material(MaterialSpec{mr, test_fiber()});
  EXPECT_STREQ(base->name(), "mooney-rivlin");
  EXPECT_STREQ(composite->name(), "mooney-rivlin+fiber");
  EXPECT_EQ(composite->initial_shear_modulus(), base->initial_shear_modulus());
  EXPECT_EQ(composite->initial_bulk_modulus(), base->initial_bulk_modulus());
  const auto* as_composite = dynamic_cast<const CompositeMaterial*>(composite.get());
  ASSERT_NE(as_composite, nullptr);
  EXPECT_NEAR(as_composite->fiber().direction.norm(), 1.0, 1e-15);
}

TEST(CompositeMaterial, FiberStiffensOnlyAlongItsDirection) {
  const NeoHookeanParams nh{1.0, 2.0};
  FiberParams fiber = test_fiber();
  fiber.direction = Vector3::UnitX();
  const MaterialPtr base = make_material(MaterialSpec{nh, std::nullopt});
  const MaterialPtr composite = make_material(MaterialSpec{nh, fiber});
  // Stretch along the fiber: more energy than the base law.
  const Matrix3 along = Vector3(1.2, 1.0, 1.0).asDiagonal();
  EXPECT_GT(composite->energy_density(along), base->energy_density(along) + 1e-3);
  // Stretch across the fiber (d . C d = 1): same energy and stress.
  const Matrix3 across = Vector3(1.0, 1.2, 0.9).asDiagonal();
  EXPECT_DOUBLE_EQ(composite->energy_density(across), base->energy_density(across));
  EXPECT_LT((composite->first_piola(across) - base->first_piola(across)).norm(), 1e-14);
}

TEST(FiberReinforcement, EnergyOfStretchIsNonNegativeConvexWithMinimumAtRest) {
  const FiberParams fiber = test_fiber();
  for (double x = 0.05; x < 4.0; x += 0.05) {
    const FiberEnergy e = fiber_energy_of_stretch(fiber, x);
    EXPECT_GE(e.psi, 0.0) << "x = " << x;
    EXPECT_GT(e.d2psi, 0.0);
    const double h = 1e-6;
    const FiberEnergy plus = fiber_energy_of_stretch(fiber, x + h);
    const FiberEnergy minus = fiber_energy_of_stretch(fiber, x - h);
    EXPECT_NEAR(e.dpsi, (plus.psi - minus.psi) / (2 * h), 1e-7 * std::max(1.0, std::abs(e.dpsi)));
    EXPECT_NEAR(e.d2psi, (plus.dpsi - minus.dpsi) / (2 * h), 1e-7 * std::max(1.0, e.d2psi));
  }
  const FiberEnergy rest = fiber_energy_of_stretch(fiber, 1.0);
  EXPECT_EQ(rest.psi, 0.0);
  EXPECT_EQ(rest.dpsi, 0.0);
  // The header's formula, alpha exp(beta (x - 1)) - alpha beta x - alpha (1 - beta).
  const double x = 1.7;
  const double formula = fiber.alpha * std::exp(fiber.beta * (x - 1)) - fiber.alpha * fiber.beta * x -
                         fiber.alpha * (1 - fiber.beta);
  EXPECT_NEAR(fiber_energy_of_stretch(fiber, x).psi, formula, 1e-14 * std::abs(formula));
}

}  // namespace
}  // namespace sinew::material
