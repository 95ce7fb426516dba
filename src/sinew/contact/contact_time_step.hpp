#pragma once
/// @file contact_time_step.hpp
/// The stiffest contact oscillation an explicit integrator must resolve. A surface node a of
/// tributary area A_a (a third of its triangles' areas) pressing a penetration g into a body
/// with penalty ε meets a force of about ε g A_a (the depth grows like the distance near the
/// surface), a spring of stiffness ε A_a on a node of mass m_a; both sides of the contact move,
/// so ω_a² ≈ 2 ε_a A_a / m_a with ε_a the largest penalty of the node's body against any body.

#include "sinew/contact/contact_energy.hpp"

namespace sinew::contact {

struct ContactTimeStep {
  double dt = 0;          ///< 2 / ω_max (time); +inf without contact or movable surface nodes
  Index critical_node = -1;
  double omega_max = 0;   ///< rad / time
};

/// `rest`: #V x 3 positions (areas are taken there); `nodal_mass`: #V lumped masses of the
/// nodes that move freely (0 for fixed, prescribed and rigid-body nodes, which are skipped).
ContactTimeStep contact_critical_time_step(const ContactGeometry& geometry, const Positions& rest,
                                           const VectorX& nodal_mass);

}  // namespace sinew::contact
