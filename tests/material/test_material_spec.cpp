/// @file test_material_spec.cpp
/// validate() and make_material(): every bad parameter is rejected with a message naming the
/// law, the parameter and the value; good parameter sets build the right law.

#include "sinew/material/material_spec.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "sinew/core/error.hpp"
#include "sinew/material/mooney_rivlin.hpp"
#include "sinew/material/neo_hookean.hpp"
#include "sinew/material/veronda_westmann.hpp"

namespace sinew::material {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

const MooneyRivlinParams kGoodMR{1.0, 0.5, 2.0};
const VerondaWestmannParams kGoodVW{1.0, 1.0, 1.0};
const NeoHookeanParams kGoodNH{1.0, 1.0};
const FiberParams kGoodFiber{0.5, 2.0, Vector3(0.0, 0.0, 3.0)};

/// The message validate(spec) throws; fails the test if it does not throw InputError.
std::string rejection_message(const MaterialSpec& spec) {
  try {
    validate(spec);
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "validate() accepted an invalid spec";
  return {};
}

struct BadParameter {
  std::string law;        ///< expected in the message
  std::string parameter;  ///< expected in the message
  MaterialSpec spec;
};

/// One spec per (parameter, bad value): NaN, +inf, negative, and zero where zero is not allowed.
std::vector<BadParameter> bad_parameters() {
  std::vector<BadParameter> cases;
  for (const double bad : {kNaN, kInf, -kInf, -1.0, 0.0}) {
    auto mr = kGoodMR;
    mr.C1 = bad;
    cases.push_back({"mooney-rivlin", "C1", {mr, std::nullopt}});
    mr = kGoodMR;
    mr.a = bad;
    cases.push_back({"mooney-rivlin", "a", {mr, std::nullopt}});
    auto vw = kGoodVW;
    vw.alpha = bad;
    cases.push_back({"veronda-westmann", "alpha", {vw, std::nullopt}});
    vw = kGoodVW;
    vw.beta = bad;
    cases.push_back({"veronda-westmann", "beta", {vw, std::nullopt}});
    vw = kGoodVW;
    vw.a = bad;
    cases.push_back({"veronda-westmann", "a", {vw, std::nullopt}});
    auto nh = kGoodNH;
    nh.mu = bad;
    cases.push_back({"neo-hookean", "mu", {nh, std::nullopt}});
    auto fiber = kGoodFiber;
    fiber.beta = bad;
    cases.push_back({"fiber", "beta", {kGoodMR, fiber}});
  }
  // Parameters that may be zero but not negative or non-finite.
  for (const double bad : {kNaN, kInf, -1e-3}) {
    auto mr = kGoodMR;
    mr.C2 = bad;
    cases.push_back({"mooney-rivlin", "C2", {mr, std::nullopt}});
    auto nh = kGoodNH;
    nh.lambda = bad;
    cases.push_back({"neo-hookean", "lambda", {nh, std::nullopt}});
    auto fiber = kGoodFiber;
    fiber.alpha = bad;
    cases.push_back({"fiber", "alpha", {kGoodVW, fiber}});
  }
  for (const Vector3& direction : {Vector3(0, 0, 0), Vector3(kNaN, 1, 0), Vector3(0, kInf, 0),
                                   Vector3(1e300, 1e300, 0)}) {
    auto fiber = kGoodFiber;
    fiber.direction = direction;
    cases.push_back({"fiber", "direction", {kGoodNH, fiber}});
  }
  return cases;
}

TEST(MaterialSpec, RejectsEveryBadParameterNamingIt) {
  const auto cases = bad_parameters();
  ASSERT_GT(cases.size(), 40u);
  for (const BadParameter& bad : cases) {
    const std::string message = rejection_message(bad.spec);
    EXPECT_THAT(message, AllOf(HasSubstr(bad.law + ": "), HasSubstr(bad.parameter + " must be")))
        << "message: " << message;
    EXPECT_THROW(make_material(bad.spec), InputError) << message;
  }
}

TEST(MaterialSpec, MessageStatesRuleAndValue) {
  auto mr = kGoodMR;
  mr.C1 = -1.0;
  EXPECT_EQ(rejection_message({mr, std::nullopt}), "mooney-rivlin: C1 must be > 0, got -1");
  auto nh = kGoodNH;
  nh.lambda = -2.5;
  EXPECT_EQ(rejection_message({nh, std::nullopt}), "neo-hookean: lambda must be >= 0, got -2.5");
  auto vw = kGoodVW;
  vw.beta = kNaN;
  EXPECT_EQ(rejection_message({vw, std::nullopt}),
            "veronda-westmann: beta must be a finite number, got nan");
  vw = kGoodVW;
  vw.alpha = 0.0;
  EXPECT_EQ(rejection_message({vw, std::nullopt}), "veronda-westmann: alpha must be > 0, got 0");
  auto fiber = kGoodFiber;
  fiber.direction = Vector3::Zero();
  EXPECT_EQ(rejection_message({kGoodMR, fiber}),
            "fiber: direction must be finite and non-zero, got (0, 0, 0)");
}

TEST(MaterialSpec, RejectsVerondaWestmannWithNonPositiveInitialBulkModulus) {
  // kappa0 = 4 a + 4 alpha beta^2 - 4/3 alpha beta: alpha = 1, beta = 0.1, a = 0.001 gives
  // 0.004 + 0.04 - 0.1333 < 0 although every parameter is positive.
  const VerondaWestmannParams soft{1.0, 0.1, 0.001};
  EXPECT_LT(veronda_westmann_bulk_modulus(soft), 0.0);
  const std::string message = rejection_message({soft, std::nullopt});
  EXPECT_THAT(message, AllOf(HasSubstr("veronda-westmann: the initial bulk modulus"),
                             HasSubstr("4 a + 4 alpha beta^2 - 4/3 alpha beta"),
                             HasSubstr("a must exceed alpha beta (1/3 - beta) = 0.0233"),
                             HasSubstr("got a = 0.001")));
  EXPECT_THROW(VerondaWestmann{soft}, InputError);
  // Just above the threshold a = alpha beta (1/3 - beta) the set is accepted.
  const double threshold = 1.0 * 0.1 * (1.0 / 3.0 - 0.1);
  EXPECT_NO_THROW(validate(MaterialSpec{VerondaWestmannParams{1.0, 0.1, threshold * 1.01}, std::nullopt}));
  EXPECT_THROW(validate(MaterialSpec{VerondaWestmannParams{1.0, 0.1, threshold * 0.99}, std::nullopt}),
               InputError);
}

TEST(MaterialSpec, RejectsParametersWhoseModuliOverflow) {
  const VerondaWestmannParams huge{1e200, 1e200, 1.0};
  EXPECT_THAT(rejection_message({huge, std::nullopt}), HasSubstr("modulus"));
}

TEST(MaterialSpec, AcceptsBoundaryValues) {
  EXPECT_NO_THROW(validate(MaterialSpec{MooneyRivlinParams{1.0, 0.0, 1.0}, std::nullopt}));
  EXPECT_NO_THROW(validate(MaterialSpec{NeoHookeanParams{1.0, 0.0}, std::nullopt}));
  EXPECT_NO_THROW(validate(MaterialSpec{kGoodNH, FiberParams{0.0, 1.0, Vector3::UnitY()}}));
}

TEST(MaterialSpec, ConstructorsValidateToo) {
  EXPECT_THROW(MooneyRivlin(MooneyRivlinParams{-1.0, 0.0, 1.0}), InputError);
  EXPECT_THROW(NeoHookean(NeoHookeanParams{0.0, 1.0}), InputError);
  EXPECT_THROW(VerondaWestmann(VerondaWestmannParams{1.0, kNaN, 1.0}), InputError);
}

TEST(MaterialSpec, MakeMaterialBuildsTheRequestedLaw) {
  EXPECT_STREQ(make_material({kGoodMR, std::nullopt})->name(), "mooney-rivlin");
  EXPECT_STREQ(make_material({kGoodVW, std::nullopt})->name(), "veronda-westmann");
  EXPECT_STREQ(make_material({kGoodNH, std::nullopt})->name(), "neo-hookean");
  EXPECT_STREQ(make_material({kGoodVW, kGoodFiber})->name(), "veronda-westmann+fiber");
  // Parameters reach the law: the moduli follow the documented formulas.
  const MaterialPtr mr = make_material({kGoodMR, std::nullopt});
  EXPECT_DOUBLE_EQ(mr->initial_shear_modulus(), 2.0 * (1.0 + 0.5));
  EXPECT_DOUBLE_EQ(mr->initial_bulk_modulus(), 4.0 / 3.0 * 1.0 + 16.0 / 3.0 * 0.5 + 4.0 * 2.0);
  const MaterialPtr vw = make_material({kGoodVW, std::nullopt});
  EXPECT_DOUBLE_EQ(vw->initial_shear_modulus(), 1.0);
  EXPECT_DOUBLE_EQ(vw->initial_bulk_modulus(), 4.0 + 4.0 - 4.0 / 3.0);
  const MaterialPtr nh = make_material({NeoHookeanParams{2.0, 5.0}, std::nullopt});
  EXPECT_DOUBLE_EQ(nh->initial_shear_modulus(), 2.0);
  EXPECT_DOUBLE_EQ(nh->initial_bulk_modulus(), 5.0 + 4.0 / 3.0);
}

TEST(MaterialSpec, FiberDirectionIsNormalized) {
  // Same fiber given with directions of different lengths: same material.
  FiberParams unit = kGoodFiber;
  unit.direction = Vector3(0.0, 0.6, 0.8);
  FiberParams scaled = kGoodFiber;
  scaled.direction = Vector3(0.0, 6.0, 8.0);
  const MaterialPtr a = make_material({kGoodNH, unit});
  const MaterialPtr b = make_material({kGoodNH, scaled});
  Matrix3 F = Matrix3::Identity();
  F(1, 1) = 1.3;
  F(2, 1) = 0.2;
  EXPECT_NEAR(a->energy_density(F), b->energy_density(F), 1e-14);
  EXPECT_GT(a->energy_density(F), make_material({kGoodNH, std::nullopt})->energy_density(F));
}

}  // namespace
}  // namespace sinew::material
