#pragma once
/// @file fiber_reinforcement.hpp
/// Fiber term added to a base law (docs/theory.md):
///   psi_f = alpha exp(beta (x - 1)) - alpha beta x - alpha (1 - beta),   x = lambda^2 = d . C d,
/// d the unit rest fiber direction. psi_f(I) = 0 and dpsi_f/dx(1) = 0, so the term is
/// stress-free at rest; d2psi_f/dx2 = alpha beta^2 exp(beta (x - 1)) > 0 (convex in x).
/// Small-strain effect: psi_f ~ 2 alpha beta^2 (d . eps d)^2, i.e. an extra uniaxial
/// stiffness 4 alpha beta^2 along d only (no shear or bulk contribution).

#include "sinew/material/material_spec.hpp"

namespace sinew::material {

/// psi_f as a function of x = lambda^2 and its first two derivatives in x (stress units).
struct FiberEnergy {
  double psi = 0;    ///< psi_f(x)
  double dpsi = 0;   ///< dpsi_f/dx
  double d2psi = 0;  ///< d2psi_f/dx2
};

/// psi_f(x) and derivatives; uses expm1 so that psi_f is accurate near x = 1.
FiberEnergy fiber_energy_of_stretch(const FiberParams& params, double stretch_squared);

/// Adds the fiber term at F to *P (3x3) and *dPdF (9x9) when non-null and returns psi_f.
/// params.direction must have unit length. Does not check det F (the base law does).
///   d x/dF = 2 F d d^T,   d2x/dF2 = 2 (d d^T) (x) Id3   (vec convention of material.hpp).
double accumulate_fiber_term(const FiberParams& params, const Matrix3& F, Matrix3* P, Matrix9* dPdF);

/// Small-strain stiffness the fiber adds along d: 4 alpha beta^2 (stress units).
double fiber_initial_axial_modulus(const FiberParams& params);

/// Throws InputError unless alpha >= 0, beta > 0 (finite) and the direction is finite and
/// non-zero.
void validate(const FiberParams& params);

}  // namespace sinew::material
