#pragma once
/// @file contact_enforcement.hpp
/// How hard the contact constraint is enforced beyond the plain penalty (docs/contact.md,
/// "Penetration control"; dissertation §6.4, §9.3.2 and §10.1.2):
///  - adaptive penalty: between load or time steps, the penalty of every body pair whose
///    largest penetration exceeds a tolerance grows in proportion (penetration ~ 1 / ε);
///  - augmented Lagrangian (Uzawa): a contact pressure p per surface node, interpolated
///    linearly over each triangle, adds ∫ p r(g) da to the pair energies, r a C¹ ramp from
///    the surface to the depth δ (pair_integral.hpp); after each converged Newton solve p_i
///    grows by ε times the deepest penetration on node i's triangles, and the step is solved
///    again until the largest penetration is below the tolerance.
/// Free functions over a CollisionSet and a ContactReport: nothing here knows the FE model.
/// Units: lengths L, penalties force / L³, pressures force / L².

#include "sinew/contact/collision_set.hpp"
#include "sinew/contact/contact_report.hpp"
#include "sinew/core/enum_names.hpp"

namespace sinew::contact {

enum class ContactEnforcement {
  Penalty,             ///< the penalty as given (the default)
  AdaptivePenalty,     ///< penalties grow between steps until the penetration is below the tolerance
  AugmentedLagrangian  ///< Uzawa multiplier updates within each step
};

/// Scene names of ContactEnforcement.
inline constexpr NameTable<ContactEnforcement, 3> kContactEnforcementNames{{
    {ContactEnforcement::Penalty, "penalty"},
    {ContactEnforcement::AdaptivePenalty, "adaptive-penalty"},
    {ContactEnforcement::AugmentedLagrangian, "augmented-lagrangian"},
}};
constexpr const auto& enum_names(ContactEnforcement) { return kContactEnforcementNames; }

struct ContactEnforcementOptions {
  ContactEnforcement method = ContactEnforcement::Penalty;
  /// Largest penetration the run aims at (L, > 0 unless method is Penalty).
  double penetration_tolerance = 0;
  /// Augmented Lagrangian: most multiplier updates (re-solves) per step.
  int max_updates = 20;
  /// Adaptive penalty: largest growth factor of a pair's penalty per step (> 1).
  double max_growth = 10;
};

/// The Uzawa update of the nodal contact pressures of `collisions` at its current positions:
/// for each surface node i, p_i + ε g_i, g_i the deepest penetration on the supports of the
/// pairs of its triangles, or 0 where none of its triangles' area penetrates (the node has left
/// contact). Starts from collisions.pressure(), or 0. Returns #V pressures (force / L²).
/// The deepest point, not the area average: at a corner the penetration concentrates at one
/// point, and the average grew the pressure there too slowly (docs/contact.md, "Augmented
/// Lagrangian"); a pressure larger than needed only lets its points rest shallower than the
/// onset depth δ (pair_integral.hpp).
VectorX updated_contact_pressure(const CollisionSet& collisions);

/// The body-pair penalties after one adaptive step: an entry (a, b) whose largest penetration
/// in `report` exceeds `tolerance` is multiplied by min(max_growth, 2 g / tolerance): it aims at
/// half the tolerance (penetration ~ 1 / ε), so that a load that keeps growing over the next
/// step stays below it. The others are kept. `penalty` is #B x #B, symmetric.
MatrixX grown_penalty(const MatrixX& penalty, const ContactReport& report, double tolerance, double max_growth);

/// The mean edge length of the contact surface triangles (L), the "element size" a relative
/// penetration tolerance refers to; 0 without triangles.
double mean_surface_edge(const ContactGeometry& geometry, const Positions& x);

}  // namespace sinew::contact
