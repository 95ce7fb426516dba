#pragma once
/// @file invariants.hpp
/// Invariants of the right Cauchy-Green tensor C = F^T F and their first and second
/// derivatives with respect to F, in closed form (docs/theory.md):
///   I1 = tr C,  I2 = 1/2 (I1^2 - tr C^2),  I3 = det C = J^2,  J = det F.
/// Derivatives use the vec convention of material.hpp: vec(A)[i + 3 j] = A(i, j), so a
/// gradient is a 9-vector and a Hessian a symmetric 9x9 matrix. All quantities are
/// dimensionless (F is).

#include <limits>

#include "sinew/core/types.hpp"

namespace sinew::material {

/// vec(A): the 9 entries of A, column-major (vec(A)[i + 3 j] = A(i, j)).
inline Vector9 vec(const Matrix3& A) { return Eigen::Map<const Vector9>(A.data()); }

/// Inverse of vec: the 3x3 matrix whose column-major entries are v.
inline Matrix3 unvec(const Vector9& v) { return Eigen::Map<const Matrix3>(v.data()); }

/// The invariants a law depends on, at one F.
struct Invariants {
  double I1 = 3;  ///< tr C
  double I2 = 3;  ///< 1/2 (I1^2 - tr C^2)
  double J = 1;   ///< det F (I3 = J^2)
};

/// I1, I2 and J of F (3x3).
Invariants compute_invariants(const Matrix3& F);

/// Cofactor matrix cof F = J F^{-T} (3x3), computed from cross products of the columns of
/// F, so it is well defined (and polynomial) even for singular F.
Matrix3 cofactor(const Matrix3& F);

/// dI1/dF = 2 F, as a 9-vector.
Vector9 d_I1_dF(const Matrix3& F);
/// d2I1/dF2 = 2 Id9 (9x9), independent of F.
Matrix9 d2_I1_dF2();

/// dI2/dF = 2 (I1 F - F C), as a 9-vector.
Vector9 d_I2_dF(const Matrix3& F);
/// d2I2/dF2 (9x9) = 2 I1 Id9 + 4 vec(F) vec(F)^T - 2 (C (x) Id3 + Id3 (x) F F^T + T),
/// with T[(i,j),(k,l)] = F(i,l) F(k,j) (the term from the transpose in C = F^T F).
Matrix9 d2_I2_dF2(const Matrix3& F);

/// dJ/dF = vec(cof F), 9-vector.
Vector9 d_J_dF(const Matrix3& F);
/// d2J/dF2 (9x9): zero 3x3 diagonal blocks; block (a, b) is d(col a of cof F)/d(col b of F),
/// a skew matrix [f_c]x built from the remaining column c of F, with sign of (a b c).
Matrix9 d2_J_dF2(const Matrix3& F);

/// dI3/dF = 2 J vec(cof F), 9-vector.
Vector9 d_I3_dF(const Matrix3& F);
/// d2I3/dF2 = 2 dJ/dF dJ/dF^T + 2 J d2J/dF2 (9x9).
Matrix9 d2_I3_dF2(const Matrix3& F);

/// A law written as psi(I1, I2, J): its value and partial derivatives at one point.
/// Order of the components: (I1, I2, J). Units: stress (psi per unit rest volume).
struct InvariantEnergy {
  double psi = 0;                            ///< energy density
  Vector3 gradient = Vector3::Zero();        ///< (dpsi/dI1, dpsi/dI2, dpsi/dJ)
  Matrix3 hessian = Matrix3::Zero();         ///< d2psi/dIk dIl, symmetric
};

/// Chain rule from (I1, I2, J) to F:
///   P = sum_k psi_k dI_k/dF,   dPdF = sum_k psi_k d2I_k/dF2 + sum_kl psi_kl dI_k/dF dI_l/dF^T.
/// Overwrites *P (3x3) and *dPdF (9x9) when non-null. Terms with zero coefficients are
/// skipped. Heap-free.
void chain_rule_from_invariants(const Matrix3& F, const InvariantEnergy& energy, Matrix3* P,
                                Matrix9* dPdF);

}  // namespace sinew::material

namespace sinew::material {

/// Evaluates a law given as psi(I1, I2, J) at F (the shared body of every isotropic law's
/// Material::evaluate). `energy_of(const Invariants&)` must return an InvariantEnergy and is
/// only called with J > 0. Returns psi (stress units), or +inf for det F <= 0 (or NaN F), in
/// which case *P and *dPdF are left untouched.
template <class EnergyOfInvariants>
double evaluate_invariant_law(const Matrix3& F, const EnergyOfInvariants& energy_of, Matrix3* P,
                              Matrix9* dPdF) {
  const Invariants invariants = compute_invariants(F);
  if (!(invariants.J > 0.0)) return std::numeric_limits<double>::infinity();
  const InvariantEnergy energy = energy_of(invariants);
  chain_rule_from_invariants(F, energy, P, dPdF);
  return energy.psi;
}

}  // namespace sinew::material
