#pragma once
/// @file time_stepping.hpp
/// Time integration of the total potential with inertia and viscosity (paper section 4,
/// dissertation section 4.8):
///  - implicit Euler in position form: each step minimizes
///      Φ(x) = Π(x, t+h) + 1/(2h²) (x - x_n - h v_n)ᵀ M (x - x_n - h v_n) + 1/(2h) (x - x_n)ᵀ D (x - x_n)
///    by Newton (the inertia and viscosity terms are QuadraticEnergy terms of the objective),
///    v_{n+1} = (x_{n+1} - x_n) / h; the steps are run_stepper's (halved on failure, grown
///    after easy steps up to max_time_step), the segments the output intervals;
///  - quasistatic: the same without inertia;
///  - explicit central differences (explicit_integration.hpp).

#include "sinew/fem/quadratic_energy.hpp"
#include "sinew/solver/solver_config.hpp"
#include "sinew/solver/stepper.hpp"

namespace sinew::solver {

/// The terms the integrator drives (owned elsewhere; they must also be terms of the objective,
/// except for the explicit integrator, which uses them directly).
struct DynamicTerms {
  fem::QuadraticEnergy* inertia = nullptr;    ///< A = M; null for quasistatic
  fem::QuadraticEnergy* viscosity = nullptr;  ///< A = D; null without damping
};

struct DynamicSetup {
  double critical_time_step = 0;  ///< explicit: 2 / ω_max (time); required > 0
  NodalVectors initial_velocity;  ///< #V x 3, or empty for rest
  /// Implicit integration: continue from this snapshot of a run of the same problem.
  const StepperSnapshot* resume = nullptr;
};

/// Integrates from t = 0 to options.end_time. StepRecord::t is the time; on_segment is called
/// at t = 0 and at every output time (multiples of output_interval, and end_time). Throws
/// InputError for options out of range and a missing inertia term.
StepperResult solve_dynamic(Objective& objective, const DynamicTerms& terms, const DynamicOptions& options,
                            const StaticSolverOptions& newton_options, const NewtonSetup& setup,
                            const DynamicSetup& dynamic_setup, const StepperCallbacks& callbacks = {},
                            StepRefinement* refinement = nullptr);

}  // namespace sinew::solver
