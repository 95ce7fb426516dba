#pragma once
/// @file composite.hpp
/// A base law plus the fiber term: psi = psi_base(F) + psi_f(F) (docs/theory.md).

#include <string>

#include "sinew/material/material.hpp"
#include "sinew/material/material_spec.hpp"

namespace sinew::material {

/// Base law + fiber reinforcement along one rest direction.
///
/// initial_shear_modulus() and initial_bulk_modulus() report the BASE law's values: the fiber
/// is stress-free at rest and adds only a uniaxial stiffness 4 alpha beta^2 along d (see
/// fiber_initial_axial_modulus), which is neither a shear nor a bulk modulus.
class CompositeMaterial final : public Material {
 public:
  /// base must be non-null (throws std::invalid_argument otherwise); the fiber parameters are
  /// validated (InputError) and the direction is normalized.
  CompositeMaterial(MaterialPtr base, const FiberParams& fiber);

  /// psi_base + psi_f; +inf (outputs untouched) when the base law rejects F (det F <= 0).
  double evaluate(const Matrix3& F, Matrix3* P, Matrix9* dPdF) const override;
  /// "<base>+fiber", e.g. "mooney-rivlin+fiber".
  const char* name() const override { return name_.c_str(); }
  double initial_shear_modulus() const override { return base_->initial_shear_modulus(); }
  double initial_bulk_modulus() const override { return base_->initial_bulk_modulus(); }

  const Material& base() const { return *base_; }
  /// The fiber parameters, direction normalized.
  const FiberParams& fiber() const { return fiber_; }

 private:
  MaterialPtr base_;
  FiberParams fiber_;
  std::string name_;
};

}  // namespace sinew::material
