/// @file scene_schema_material.cpp
/// The scene schema of a material: a hyperelastic law (docs/theory.md) and its parameters.

#include "sinew/scene/scene_schema_parts.hpp"

#include "sinew/material/material_spec.hpp"
#include "sinew/scene/schema_bounds.hpp"
#include "sinew/scene/schema_builder.hpp"

namespace sinew::scene::schema_parts {

using namespace schema_builder;  // NOLINT(google-build-using-namespace)
using namespace schema_bounds;   // NOLINT(google-build-using-namespace)
using nlohmann::json;

SchemaNode material_schema() {
  const material::MooneyRivlinParams mooney_rivlin;
  const material::FiberParams fiber;
  Key m = object("", "A hyperelastic law (docs/theory.md); stresses in the scene's stress unit",
                 {
                     string("law", "the strain-energy function")
                         .required()
                         .allowed(allowed_names<material::Law>()),
                     object("fiber",
                            "fiber reinforcement added to the law: psi_f = alpha exp(beta (lambda^2 - 1)) - alpha beta "
                            "lambda^2 + const, lambda^2 = d . C d",
                            {
                                number("alpha", "fiber stiffness (stress)").required().min(0).max(kMaxPhysical),
                                number("beta", "fiber exponent (dimensionless)").required().above(0).max(kMaxExponent),
                                vec3("direction", "rest fiber direction d (normalized on use); regions may override it")
                                    .within(kMaxLength)
                                    .nonzero()
                                    .fallback(vec3_json(fiber.direction)),
                            }),
                 });
  m.node.tag_key = "law";
  m.node.variants = {
      {key_of(material::Law::MooneyRivlin),
       "psi = C1 (I1-3) + C2 (I2-3) + a (I3-1) - (C1 + 2 C2 + a) ln I3",
       {
           number("C1", "first Mooney-Rivlin constant (stress)").required().above(0).max(kMaxPhysical),
           number("C2", "second Mooney-Rivlin constant (stress)").min(0).max(kMaxPhysical).fallback(mooney_rivlin.C2),
           number("a", "compressibility (stress)").required().above(0).max(kMaxPhysical),
       }},
      {key_of(material::Law::VerondaWestmann),
       "psi = alpha (exp(beta (I1-3)) - 1) - (alpha beta / 2)(I2-3) + a (I3-1) - a ln I3",
       {
           number("alpha", "stiffness (stress)").required().above(0).max(kMaxPhysical),
           number("beta", "exponent (dimensionless)").required().above(0).max(kMaxExponent),
           number("a", "compressibility (stress)").required().above(0).max(kMaxPhysical),
       }},
      {key_of(material::Law::NeoHookean),
       "psi = mu/2 (I1-3) - mu ln J + lambda/2 (ln J)^2",
       {
           number("mu", "shear modulus (stress)").required().above(0).max(kMaxPhysical),
           number("lambda", "first Lame parameter (stress)").required().min(0).max(kMaxPhysical),
       }},
  };
  return m;
}

}  // namespace sinew::scene::schema_parts
