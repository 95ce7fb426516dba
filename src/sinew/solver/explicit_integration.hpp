#pragma once
/// @file explicit_integration.hpp
/// Explicit central differences (velocity Verlet) in the reduced coordinates q with the lumped
/// mass M_q = Jᵀ M J and a fixed step, a safety fraction of the critical step; damping lagged
/// half a step (dissertation section 8.2). No Newton and no step control: the same callbacks
/// and result as run_stepper.

#include "sinew/solver/time_stepping.hpp"

namespace sinew::solver {

/// Integrates from t = 0 to options.end_time. Throws InputError without the (lumped) mass
/// term, without a critical time step, and when a moving part has no mass.
StepperResult solve_explicit(Objective& objective, const DynamicTerms& terms, const DynamicOptions& options,
                             const DynamicSetup& setup, const StepperCallbacks& callbacks);

}  // namespace sinew::solver
