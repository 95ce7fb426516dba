/// @file fiber_reinforcement.cpp

#include "sinew/material/fiber_reinforcement.hpp"

#include <cmath>

#include <fmt/format.h>

#include "sinew/core/error.hpp"
#include "sinew/material/parameter_checks.hpp"

namespace sinew::material {

FiberEnergy fiber_energy_of_stretch(const FiberParams& params, double stretch_squared) {
  const double alpha = params.alpha;
  const double beta = params.beta;
  const double t = beta * (stretch_squared - 1.0);
  const double exp_t = std::exp(t);
  FiberEnergy e;
  // alpha e^t - alpha beta x - alpha (1 - beta) = alpha ((e^t - 1) - beta (x - 1)).
  e.psi = alpha * (std::expm1(t) - t);
  e.dpsi = alpha * beta * std::expm1(t);
  e.d2psi = alpha * beta * beta * exp_t;
  return e;
}

double accumulate_fiber_term(const FiberParams& params, const Matrix3& F, Matrix3* P, Matrix9* dPdF) {
  const Vector3& d = params.direction;
  const Vector3 Fd = F * d;
  const FiberEnergy e = fiber_energy_of_stretch(params, Fd.squaredNorm());
  if (P == nullptr && dPdF == nullptr) return e.psi;

  const Matrix3 dx_dF = 2.0 * Fd * d.transpose();
  if (P != nullptr) *P += e.dpsi * dx_dF;
  if (dPdF != nullptr) {
    const Eigen::Map<const Vector9> g(dx_dF.data());
    Matrix9& H = *dPdF;
    H.noalias() += e.d2psi * g * g.transpose();
    for (int l = 0; l < 3; ++l) {
      for (int j = 0; j < 3; ++j) {
        H.block<3, 3>(3 * j, 3 * l).diagonal().array() += 2.0 * e.dpsi * d[j] * d[l];
      }
    }
  }
  return e.psi;
}

double fiber_initial_axial_modulus(const FiberParams& params) {
  return 4.0 * params.alpha * params.beta * params.beta;
}

void validate(const FiberParams& params) {
  constexpr const char* law = "fiber";
  require_non_negative(law, "alpha", params.alpha);
  require_positive(law, "beta", params.beta);
  const Vector3& d = params.direction;
  if (!d.allFinite() || !(d.norm() > 0.0) || !std::isfinite(d.norm())) {
    throw InputError(fmt::format("{}: direction must be finite and non-zero, got ({}, {}, {})", law,
                                 d.x(), d.y(), d.z()));
  }
}

}  // namespace sinew::material
