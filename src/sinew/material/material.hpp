#pragma once
/// @file material.hpp
/// A hyperelastic law at a point: psi(F), P(F) = dpsi/dF, dP/dF. Nothing else: no mesh,
/// no quadrature, no parsing, no output (GUIDE.md section 2).
///
/// Conventions
/// - F is the 3x3 deformation gradient (dimensionless).
/// - psi is energy per unit rest volume (stress unit of the scene, e.g. kPa).
/// - vec(A) is column-major: vec(A)[i + 3 j] = A(i, j). dPdF(k, l) = d vec(P)[k] / d vec(F)[l].
/// - For J = det F <= 0 the energy is +infinity (evaluate returns +inf and leaves P, dPdF
///   untouched); every law blows up as J -> 0+.

#include <memory>

#include "sinew/core/types.hpp"

namespace sinew::material {

class Material {
 public:
  virtual ~Material() = default;

  /// psi(F); fills *P and *dPdF when requested and non-null. Returns +inf when det F <= 0.
  virtual double evaluate(const Matrix3& F, Matrix3* P, Matrix9* dPdF) const = 0;

  /// A short human-readable name ("mooney-rivlin", ...).
  virtual const char* name() const = 0;

  /// Small-strain shear modulus mu and bulk modulus kappa at F = I (stress units); used for
  /// default penalty factors, stable time steps and load scales.
  virtual double initial_shear_modulus() const = 0;
  virtual double initial_bulk_modulus() const = 0;

  // Convenience wrappers.
  double energy_density(const Matrix3& F) const { return evaluate(F, nullptr, nullptr); }
  Matrix3 first_piola(const Matrix3& F) const {
    Matrix3 P;
    evaluate(F, &P, nullptr);
    return P;
  }
  Matrix9 first_piola_derivative(const Matrix3& F) const {
    Matrix3 P;
    Matrix9 dPdF;
    evaluate(F, &P, &dPdF);
    return dPdF;
  }
};

using MaterialPtr = std::shared_ptr<const Material>;

}  // namespace sinew::material
