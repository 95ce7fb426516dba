/// @file scene_schema_contact.cpp
/// The scene schema of the contact section (docs/theory.md).

#include "sinew/scene/scene_schema_parts.hpp"

#include "sinew/scene/scene_config.hpp"
#include "sinew/scene/schema_bounds.hpp"
#include "sinew/scene/schema_builder.hpp"

namespace sinew::scene::schema_parts {

using namespace schema_builder;  // NOLINT(google-build-using-namespace)
using namespace schema_bounds;   // NOLINT(google-build-using-namespace)
using nlohmann::json;

SchemaNode contact_schema() {
  const ContactConfig defaults;
  return object(
      "contact",
      "material-depth contact between all bodies, self-contact included (docs/theory.md): the energy "
      "(penalty/2) * integral of depth^2 over every boundary-triangle / tet intersection. Omit for no contact.",
      {
          choice("method",
                 "\"area\": exact integral over triangle-tet intersections (continuous forces); "
                 "\"point\": the seed's collocation at triangle vertices (baseline)",
                 defaults.method),
          choice("hessian",
                 "contact stiffness: \"exact\" (the exact second derivative), \"projected\" (exact, each pair "
                 "projected onto the positive semi-definite cone) or \"gauss-newton\" (positive semi-definite, "
                 "frozen areas; cheapest, converges slowly where contact areas change)",
                 defaults.hessian),
          number("penalty",
                 "penalty for every pair of bodies (force / length^3: a penetration g meets a pressure of about "
                 "penalty * g); default: penalty_scale * E / h per pair of bodies")
              .max(kMaxPenalty)
              .above(0),
          number("penalty_scale",
                 "automatic penalty = penalty_scale * E / h, E the smaller initial Young's modulus of the two bodies "
                 "(rigid bodies take the other's), h the smaller mean boundary edge length")
              .max(kMaxScale)
              .above(0)
              .fallback(defaults.penalty_scale),
          boolean("self_contact", "a body's surface may also penetrate the same body").fallback(defaults.self_contact),
          object("friction",
                 "Coulomb friction (docs/contact.md, \"Friction\"): a smoothed, lagged dissipative potential "
                 "integrated over the same triangle-tet polygons as the normal contact; the normal forces and "
                 "tangent directions are taken at the start of each load or time step and refreshed after each "
                 "converged solve until the total normal force changes by less than the tolerance",
                 {
                     number("coefficient", "friction coefficient of every pair of bodies without its own (0: none)")
                         .min(0)
                         .max(100)
                         .fallback(defaults.friction.coefficient),
                     number("slip_threshold",
                            "tangential slip per step (length) below which friction grows smoothly from 0 (static "
                            "friction is approximated by this much creep); default 1e-3 of the mean edge length of "
                            "the contact surfaces")
                         .above(0)
                         .max(kMaxLength),
                     number("slip_velocity_threshold",
                            "dynamics: a slip threshold in velocity units (length / time); each time step of size h "
                            "uses slip_threshold = this * h, so that what sticks creeps slower than this whatever "
                            "the step size; instead of slip_threshold")
                         .above(0)
                         .max(kMaxLength),
                     integer("max_updates", "refreshes of the lagged normal forces per step at most")
                         .min(0)
                         .max(100)
                         .fallback(defaults.friction.max_updates),
                     number("tolerance", "relative change of the total normal force below which the refreshes stop")
                         .above(0)
                         .max(1)
                         .fallback(defaults.friction.tolerance),
                 })
              .fallback(json::object()),
          object("enforcement",
                 "penetration control beyond the plain penalty (docs/contact.md, \"Penetration control\"): "
                 "\"adaptive-penalty\" grows the penalty of a pair of bodies between steps while its largest "
                 "penetration exceeds the tolerance; \"augmented-lagrangian\" adds a nodal contact pressure "
                 "updated after each converged Newton solve (Uzawa) and solves the step again until the largest "
                 "penetration is below the tolerance. Give penetration_tolerance or relative_tolerance with either.",
                 {
                     choice("method", "\"penalty\" (as given), \"adaptive-penalty\" or \"augmented-lagrangian\"",
                            defaults.enforcement.method),
                     number("penetration_tolerance", "largest penetration aimed at (length)").above(0).max(kMaxLength),
                     number("relative_tolerance",
                            "the same as a fraction of the mean edge length of the contact surfaces")
                         .above(0)
                         .max(1),
                     integer("max_updates",
                             "augmented Lagrangian: most multiplier updates (re-solves) per step; the step is "
                             "accepted after them even if the penetration is still above the tolerance")
                         .min(1)
                         .max(1000)
                         .fallback(defaults.enforcement.max_updates),
                     number("max_growth", "adaptive penalty: largest growth factor of a penalty per step")
                         .above(1)
                         .max(1e6)
                         .fallback(defaults.enforcement.max_growth),
                 })
              .fallback(json::object()),
          array("pairs", "per pair of bodies: a penalty of its own, or no contact",
                object("", "one pair of bodies (the same name twice for self-contact)",
                       {
                           array("bodies", "two body names", string("", "body name").non_empty()).required().items(2, 2),
                           number("penalty", "penalty of this pair (force / length^3)").above(0).max(kMaxPenalty),
                           number("friction", "Coulomb friction coefficient of this pair (default: friction.coefficient)")
                               .min(0)
                               .max(100),
                           boolean("enabled", "false: these bodies do not touch").fallback(true),
                       }))
              .fallback(json::array()),
      });
}

}  // namespace sinew::scene::schema_parts
