#pragma once
/// @file reactions.hpp
/// Reaction forces and moments that constraints exert on the bodies. At a constrained node a,
/// equilibrium reads -dE/dx_a + f_a + r_a = 0, so the support's force is r_a = dPi/dx_a
/// (Pi = E - f.x): the force the support applies to the body.

#include <string>
#include <vector>

#include "sinew/fem/dof_map.hpp"

namespace sinew::fem {

struct Reaction {
  std::string name;        ///< boundary condition or rigid body name
  Vector3 force = Vector3::Zero();   ///< total force on the body from the constraint (force unit)
  Vector3 moment = Vector3::Zero();  ///< about `moment_point` (force x length)
  Vector3 moment_point = Vector3::Zero();  ///< current position of the motion's axis point, or the body center
};

/// One entry per prescribed set, per planar set (normal component only), per rigid body.
/// `full_gradient`: dPi/dx at `state` (#V x 3).
std::vector<Reaction> compute_reactions(const Problem& problem, const DofMap& dofs, const State& state,
                                        const NodalVectors& full_gradient);

}  // namespace sinew::fem
