#pragma once
/// @file prescribed_turn.hpp
/// A bound on how far a prescribed motion may turn a body in one load or time step. A rotation
/// is periodic: 360 degrees in one step lands on the rest pose and the solve would see no
/// motion at all (and 180 degrees is ambiguous). Steps are shortened so that no prescribed
/// motion turns anything by more than kMaxPrescribedTurnPerStep (docs/solver.md).

#include <numbers>

#include "sinew/fem/dof_map.hpp"

namespace sinew::solver {

/// Largest rotation (radians) of a prescribed motion within one step: 30 degrees.
inline constexpr double kMaxPrescribedTurnPerStep = std::numbers::pi / 6;

/// `size` (a step of the load parameter from `from`), halved until no prescribed motion turns
/// by more than kMaxPrescribedTurnPerStep over [from, from + size]; stops halving below
/// `smallest` and returns the last size tried (the caller reports it as too small).
double step_within_turn_bound(const fem::DofMap& dofs, double from, double size, double smallest);

}  // namespace sinew::solver
