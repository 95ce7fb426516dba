#pragma once
/// @file mooney_rivlin.hpp
/// Compressible Mooney-Rivlin law in the paper's form (docs/theory.md):
///   psi = C1 (I1 - 3) + C2 (I2 - 3) + a (I3 - 1) - (C1 + 2 C2 + a) ln I3,
/// with I2 = 1/2 (I1^2 - tr C^2) (not tr C^2 as in the dissertation).
/// Written here in J = det F: a (J^2 - 1) - 2 (C1 + 2 C2 + a) ln J.

#include "sinew/material/invariants.hpp"
#include "sinew/material/material.hpp"
#include "sinew/material/material_spec.hpp"

namespace sinew::material {

/// psi(I1, I2, J) and its partial derivatives (stress units). Requires J > 0.
InvariantEnergy mooney_rivlin_energy(const MooneyRivlinParams& params, const Invariants& invariants);

/// Small-strain shear modulus mu0 = 2 (C1 + C2) (stress units).
double mooney_rivlin_shear_modulus(const MooneyRivlinParams& params);
/// Small-strain bulk modulus kappa0 = 4/3 C1 + 16/3 C2 + 4 a (stress units).
double mooney_rivlin_bulk_modulus(const MooneyRivlinParams& params);

/// Throws InputError unless C1 > 0, C2 >= 0, a > 0, all finite (and the initial moduli are
/// finite and positive, which then holds up to overflow).
void validate(const MooneyRivlinParams& params);

/// The Mooney-Rivlin law as a Material. The constructor validates the parameters.
class MooneyRivlin final : public Material {
 public:
  explicit MooneyRivlin(const MooneyRivlinParams& params);

  double evaluate(const Matrix3& F, Matrix3* P, Matrix9* dPdF) const override;
  const char* name() const override { return name_of(Law::MooneyRivlin).data(); }
  double initial_shear_modulus() const override { return mooney_rivlin_shear_modulus(params_); }
  double initial_bulk_modulus() const override { return mooney_rivlin_bulk_modulus(params_); }

  const MooneyRivlinParams& params() const { return params_; }

 private:
  MooneyRivlinParams params_;
};

}  // namespace sinew::material
