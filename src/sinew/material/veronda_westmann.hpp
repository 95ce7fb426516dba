#pragma once
/// @file veronda_westmann.hpp
/// Veronda-Westmann law in a consistent, stress-free form (docs/theory.md):
///   psi = alpha (exp(beta (I1 - 3)) - 1) - (alpha beta / 2)(I2 - 3) + a (I3 - 1) - a ln I3.
/// (The paper's 2 alpha exp(I1 - 3) + alpha beta (I2 - 3) + ... is not stress-free at rest.)
/// Written here in J = det F: a (J^2 - 1) - 2 a ln J.

#include "sinew/material/invariants.hpp"
#include "sinew/material/material.hpp"
#include "sinew/material/material_spec.hpp"

namespace sinew::material {

/// psi(I1, I2, J) and its partial derivatives (stress units). Requires J > 0.
InvariantEnergy veronda_westmann_energy(const VerondaWestmannParams& params,
                                        const Invariants& invariants);

/// Small-strain shear modulus mu0 = alpha beta (stress units).
double veronda_westmann_shear_modulus(const VerondaWestmannParams& params);
/// Small-strain bulk modulus kappa0 = 4 a + 4 alpha beta^2 - 4/3 alpha beta (stress units).
/// It is NOT positive for every alpha, beta, a > 0: it needs a > alpha beta (1/3 - beta).
double veronda_westmann_bulk_modulus(const VerondaWestmannParams& params);

/// Throws InputError unless alpha > 0, beta > 0, a > 0, all finite, and kappa0 > 0.
void validate(const VerondaWestmannParams& params);

/// The Veronda-Westmann law as a Material. The constructor validates the parameters.
class VerondaWestmann final : public Material {
 public:
  explicit VerondaWestmann(const VerondaWestmannParams& params);

  double evaluate(const Matrix3& F, Matrix3* P, Matrix9* dPdF) const override;
  const char* name() const override { return name_of(Law::VerondaWestmann).data(); }
  double initial_shear_modulus() const override { return veronda_westmann_shear_modulus(params_); }
  double initial_bulk_modulus() const override { return veronda_westmann_bulk_modulus(params_); }

  const VerondaWestmannParams& params() const { return params_; }

 private:
  VerondaWestmannParams params_;
};

}  // namespace sinew::material
