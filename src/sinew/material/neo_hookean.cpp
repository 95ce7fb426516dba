/// @file neo_hookean.cpp
///
/// Small-strain moduli: linearizing P = mu (F - F^{-T}) + lambda ln J F^{-T} at F = I + H
/// gives P ~ mu (H + H^T) + lambda tr(H) I, i.e. Lame constants (lambda, mu), so
///   mu0 = mu,  kappa0 = lambda + 2/3 mu.
/// (Same as the general formula of mooney_rivlin.cpp with psi_1 = mu/2, psi_2 = 0,
/// psi_3 = -mu/2, psi_33 = mu/2 + lambda/4.)

#include "sinew/material/neo_hookean.hpp"

#include <cmath>

#include "sinew/material/parameter_checks.hpp"

namespace sinew::material {

InvariantEnergy neo_hookean_energy(const NeoHookeanParams& params, const Invariants& invariants) {
  const double mu = params.mu;
  const double lambda = params.lambda;
  const double J = invariants.J;
  const double log_J = std::log(J);
  InvariantEnergy e;
  e.psi = 0.5 * mu * (invariants.I1 - 3.0) - mu * log_J + 0.5 * lambda * log_J * log_J;
  e.gradient = Vector3(0.5 * mu, 0.0, (lambda * log_J - mu) / J);
  e.hessian(2, 2) = (mu + lambda - lambda * log_J) / (J * J);
  return e;
}

double neo_hookean_shear_modulus(const NeoHookeanParams& params) { return params.mu; }

double neo_hookean_bulk_modulus(const NeoHookeanParams& params) {
  return params.lambda + 2.0 / 3.0 * params.mu;
}

void validate(const NeoHookeanParams& params) {
  constexpr std::string_view law = name_of(Law::NeoHookean);
  require_positive(law, "mu", params.mu);
  require_non_negative(law, "lambda", params.lambda);
  require_positive_initial_moduli(law, neo_hookean_shear_modulus(params), "mu",
                                  neo_hookean_bulk_modulus(params), "lambda + 2/3 mu");
}

NeoHookean::NeoHookean(const NeoHookeanParams& params) : params_(params) { validate(params_); }

double NeoHookean::evaluate(const Matrix3& F, Matrix3* P, Matrix9* dPdF) const {
  return evaluate_invariant_law(
      F, [this](const Invariants& invariants) { return neo_hookean_energy(params_, invariants); },
      P, dPdF);
}

}  // namespace sinew::material
