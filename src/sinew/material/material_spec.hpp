#pragma once
/// @file material_spec.hpp
/// Plain parameter structs for every law (docs/theory.md) and the factory that turns
/// them into a Material. Units: stresses in the scene's stress unit; beta dimensionless.

#include <optional>
#include <string>
#include <variant>

#include "sinew/material/law.hpp"
#include "sinew/material/material.hpp"

namespace sinew::material {

/// psi = C1 (I1-3) + C2 (I2-3) + a (I3-1) - (C1 + 2 C2 + a) ln I3   (paper's form, I2 = invariant)
struct MooneyRivlinParams {
  double C1 = 0;  ///< > 0 (stress)
  double C2 = 0;  ///< >= 0 (stress)
  double a = 0;   ///< > 0, compressibility (stress)
};

/// psi = alpha (exp(beta (I1-3)) - 1) - (alpha beta / 2)(I2-3) + a (I3-1) - a ln I3
struct VerondaWestmannParams {
  double alpha = 0;  ///< > 0 (stress)
  double beta = 0;   ///< > 0 (dimensionless)
  double a = 0;      ///< > 0 (stress)
};

/// psi = mu/2 (I1-3) - mu ln J + lambda/2 (ln J)^2
struct NeoHookeanParams {
  double mu = 0;      ///< > 0 (stress)
  double lambda = 0;  ///< >= 0 (stress)
};

/// Added to a base law: psi_f = alpha exp(beta (lambda^2 - 1)) - alpha beta lambda^2 - alpha (1 - beta)
/// (the constant makes psi_f(I) = 0), lambda^2 = d . C d, d the unit rest fiber direction.
struct FiberParams {
  double alpha = 0;                  ///< >= 0 (stress)
  double beta = 0;                   ///< > 0 (dimensionless)
  Vector3 direction = Vector3::UnitX();  ///< rest direction, normalized by the factory
};

/// The base law's parameters; the alternatives are in the order of Law.
using BaseLawParams = std::variant<MooneyRivlinParams, VerondaWestmannParams, NeoHookeanParams>;

/// The law whose parameters `params` holds.
constexpr Law law_of(const BaseLawParams& params) { return static_cast<Law>(params.index()); }

struct MaterialSpec {
  BaseLawParams base;
  std::optional<FiberParams> fiber;
};

/// Checks ranges (positive stiffness, finite numbers, non-zero fiber direction).
/// Throws InputError naming the parameter, e.g. "mooney-rivlin: C1 must be > 0, got -1".
void validate(const MaterialSpec& spec);

/// Validates, then builds the law (base plus optional fiber term).
MaterialPtr make_material(const MaterialSpec& spec);

}  // namespace sinew::material
