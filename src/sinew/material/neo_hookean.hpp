#pragma once
/// @file neo_hookean.hpp
/// Compressible neo-Hookean law (for cross-checks with other solvers, docs/theory.md):
///   psi = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2.

#include "sinew/material/invariants.hpp"
#include "sinew/material/material.hpp"
#include "sinew/material/material_spec.hpp"

namespace sinew::material {

/// psi(I1, I2, J) and its partial derivatives (stress units). Requires J > 0.
InvariantEnergy neo_hookean_energy(const NeoHookeanParams& params, const Invariants& invariants);

/// Small-strain shear modulus mu0 = mu (stress units).
double neo_hookean_shear_modulus(const NeoHookeanParams& params);
/// Small-strain bulk modulus kappa0 = lambda + 2/3 mu (stress units).
double neo_hookean_bulk_modulus(const NeoHookeanParams& params);

/// Throws InputError unless mu > 0 and lambda >= 0, both finite.
void validate(const NeoHookeanParams& params);

/// The neo-Hookean law as a Material. The constructor validates the parameters.
class NeoHookean final : public Material {
 public:
  explicit NeoHookean(const NeoHookeanParams& params);

  double evaluate(const Matrix3& F, Matrix3* P, Matrix9* dPdF) const override;
  const char* name() const override { return name_of(Law::NeoHookean).data(); }
  double initial_shear_modulus() const override { return neo_hookean_shear_modulus(params_); }
  double initial_bulk_modulus() const override { return neo_hookean_bulk_modulus(params_); }

  const NeoHookeanParams& params() const { return params_; }

 private:
  NeoHookeanParams params_;
};

}  // namespace sinew::material
