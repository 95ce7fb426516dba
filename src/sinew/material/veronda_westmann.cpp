/// @file veronda_westmann.cpp
///
/// Small-strain moduli (general derivation in mooney_rivlin.cpp: mu0 = 2 (psi_1 + psi_2),
/// kappa0 = 8/3 (psi_2 + psi_3) + w^T Psi w with w = (2, 4, 2), derivatives at rest).
/// Veronda-Westmann at rest: psi_1 = alpha beta, psi_2 = -alpha beta / 2, psi_3 = a - a = 0
/// (stress-free: psi_1 + 2 psi_2 + psi_3 = 0), psi_11 = alpha beta^2, psi_33 = a, so
///   mu0 = alpha beta,
///   kappa0 = -4/3 alpha beta + 4 alpha beta^2 + 4 a.

#include "sinew/material/veronda_westmann.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "sinew/material/parameter_checks.hpp"

namespace sinew::material {

InvariantEnergy veronda_westmann_energy(const VerondaWestmannParams& params,
                                        const Invariants& invariants) {
  const double alpha = params.alpha;
  const double beta = params.beta;
  const double a = params.a;
  const double J = invariants.J;
  const double exponent = beta * (invariants.I1 - 3.0);
  const double exp_term = std::exp(exponent);
  InvariantEnergy e;
  e.psi = alpha * std::expm1(exponent) - 0.5 * alpha * beta * (invariants.I2 - 3.0) +
          a * (J * J - 1.0) - 2.0 * a * std::log(J);
  e.gradient = Vector3(alpha * beta * exp_term, -0.5 * alpha * beta, 2.0 * a * (J - 1.0 / J));
  e.hessian(0, 0) = alpha * beta * beta * exp_term;
  e.hessian(2, 2) = 2.0 * a * (1.0 + 1.0 / (J * J));
  return e;
}

double veronda_westmann_shear_modulus(const VerondaWestmannParams& params) {
  return params.alpha * params.beta;
}

double veronda_westmann_bulk_modulus(const VerondaWestmannParams& params) {
  const double alpha_beta = params.alpha * params.beta;
  return 4.0 * params.a + 4.0 * alpha_beta * params.beta - 4.0 / 3.0 * alpha_beta;
}

void validate(const VerondaWestmannParams& params) {
  constexpr std::string_view law = name_of(Law::VerondaWestmann);
  require_positive(law, "alpha", params.alpha);
  require_positive(law, "beta", params.beta);
  require_positive(law, "a", params.a);
  const double alpha_beta = params.alpha * params.beta;
  const std::string hint = fmt::format(
      "with alpha = {}, beta = {}, a must exceed alpha beta (1/3 - beta) = {}, got a = {}",
      params.alpha, params.beta, alpha_beta * (1.0 / 3.0 - params.beta), params.a);
  require_positive_initial_moduli(law, veronda_westmann_shear_modulus(params), "alpha beta",
                                  veronda_westmann_bulk_modulus(params),
                                  "4 a + 4 alpha beta^2 - 4/3 alpha beta", hint);
}

VerondaWestmann::VerondaWestmann(const VerondaWestmannParams& params) : params_(params) {
  validate(params_);
}

double VerondaWestmann::evaluate(const Matrix3& F, Matrix3* P, Matrix9* dPdF) const {
  return evaluate_invariant_law(
      F,
      [this](const Invariants& invariants) { return veronda_westmann_energy(params_, invariants); },
      P, dPdF);
}

}  // namespace sinew::material
