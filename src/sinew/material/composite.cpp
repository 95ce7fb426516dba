/// @file composite.cpp

#include "sinew/material/composite.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "sinew/material/fiber_reinforcement.hpp"

namespace sinew::material {

CompositeMaterial::CompositeMaterial(MaterialPtr base, const FiberParams& fiber)
    : base_(std::move(base)), fiber_(fiber) {
  // Programming error, not input: make_material always passes a base law.
  if (!base_) throw std::invalid_argument("CompositeMaterial: base material is null");
  validate(fiber_);
  fiber_.direction.normalize();
  name_ = std::string(base_->name()) + "+fiber";
}

double CompositeMaterial::evaluate(const Matrix3& F, Matrix3* P, Matrix9* dPdF) const {
  const double psi_base = base_->evaluate(F, P, dPdF);
  if (!std::isfinite(psi_base)) return psi_base;
  return psi_base + accumulate_fiber_term(fiber_, F, P, dPdF);
}

}  // namespace sinew::material
