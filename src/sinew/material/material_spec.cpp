/// @file material_spec.cpp
/// validate() and make_material() for MaterialSpec.

#include "sinew/material/material_spec.hpp"

#include <memory>
#include <variant>

#include "sinew/material/composite.hpp"
#include "sinew/material/fiber_reinforcement.hpp"
#include "sinew/material/mooney_rivlin.hpp"
#include "sinew/material/neo_hookean.hpp"
#include "sinew/material/veronda_westmann.hpp"

namespace sinew::material {
namespace {

MaterialPtr make_base(const MooneyRivlinParams& p) { return std::make_shared<const MooneyRivlin>(p); }
MaterialPtr make_base(const VerondaWestmannParams& p) {
  return std::make_shared<const VerondaWestmann>(p);
}
MaterialPtr make_base(const NeoHookeanParams& p) { return std::make_shared<const NeoHookean>(p); }

}  // namespace

void validate(const MaterialSpec& spec) {
  std::visit([](const auto& params) { validate(params); }, spec.base);
  if (spec.fiber) validate(*spec.fiber);
}

MaterialPtr make_material(const MaterialSpec& spec) {
  validate(spec);
  MaterialPtr base = std::visit([](const auto& params) { return make_base(params); }, spec.base);
  if (!spec.fiber) return base;
  return std::make_shared<const CompositeMaterial>(std::move(base), *spec.fiber);
}

}  // namespace sinew::material
