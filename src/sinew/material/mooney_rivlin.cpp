/// @file mooney_rivlin.cpp
///
/// Small-strain moduli of a law psi(I1, I2, I3) (derivation shared by all laws here).
/// With C = I + 2E: I1 = 3 + 2 tr E, I2 = 3 + 4 tr E + 2 ((tr E)^2 - tr E^2),
/// I3 = 1 + 2 tr E + 2 ((tr E)^2 - tr E^2) + O(E^3). Writing psi_k = dpsi/dIk and
/// psi_kl at rest and w = (2, 4, 2), the stress-free condition is psi_1 + 2 psi_2 + psi_3 = 0
/// and the quadratic part is
///   psi ~ 2 (psi_2 + psi_3) ((tr E)^2 - tr E^2) + 1/2 (w^T Psi w) (tr E)^2,
/// which matches mu tr e^2 + lambda/2 (tr e)^2, hence
///   mu0 = -2 (psi_2 + psi_3) = 2 (psi_1 + psi_2),
///   kappa0 = lambda + 2/3 mu0 = 8/3 (psi_2 + psi_3) + w^T Psi w.
/// Mooney-Rivlin: psi_1 = C1, psi_2 = C2, psi_3 = -(C1 + 2 C2), psi_33 = C1 + 2 C2 + a, so
///   mu0 = 2 (C1 + C2),  kappa0 = -8/3 (C1 + C2) + 4 (C1 + 2 C2 + a) = 4/3 C1 + 16/3 C2 + 4 a.

#include "sinew/material/mooney_rivlin.hpp"

#include <cmath>

#include "sinew/material/parameter_checks.hpp"

namespace sinew::material {

InvariantEnergy mooney_rivlin_energy(const MooneyRivlinParams& params, const Invariants& invariants) {
  const double J = invariants.J;
  const double log_coefficient = params.C1 + 2.0 * params.C2 + params.a;  // of -ln I3 = -2 ln J
  InvariantEnergy e;
  e.psi = params.C1 * (invariants.I1 - 3.0) + params.C2 * (invariants.I2 - 3.0) +
          params.a * (J * J - 1.0) - 2.0 * log_coefficient * std::log(J);
  e.gradient = Vector3(params.C1, params.C2, 2.0 * params.a * J - 2.0 * log_coefficient / J);
  e.hessian(2, 2) = 2.0 * params.a + 2.0 * log_coefficient / (J * J);
  return e;
}

double mooney_rivlin_shear_modulus(const MooneyRivlinParams& params) {
  return 2.0 * (params.C1 + params.C2);
}

double mooney_rivlin_bulk_modulus(const MooneyRivlinParams& params) {
  return 4.0 / 3.0 * params.C1 + 16.0 / 3.0 * params.C2 + 4.0 * params.a;
}

void validate(const MooneyRivlinParams& params) {
  constexpr std::string_view law = name_of(Law::MooneyRivlin);
  require_positive(law, "C1", params.C1);
  require_non_negative(law, "C2", params.C2);
  require_positive(law, "a", params.a);
  require_positive_initial_moduli(law, mooney_rivlin_shear_modulus(params), "2 (C1 + C2)",
                                  mooney_rivlin_bulk_modulus(params),
                                  "4/3 C1 + 16/3 C2 + 4 a");
}

MooneyRivlin::MooneyRivlin(const MooneyRivlinParams& params) : params_(params) { validate(params_); }

double MooneyRivlin::evaluate(const Matrix3& F, Matrix3* P, Matrix9* dPdF) const {
  return evaluate_invariant_law(
      F, [this](const Invariants& invariants) { return mooney_rivlin_energy(params_, invariants); },
      P, dPdF);
}

}  // namespace sinew::material
