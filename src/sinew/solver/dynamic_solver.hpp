#pragma once
/// @file dynamic_solver.hpp
/// Time integration of the total potential with inertia and viscosity (paper section 4,
/// dissertation section 4.8):
///  - implicit Euler in position form: each step minimizes
///      Φ(x) = Π(x, t+h) + 1/(2h²) (x - x_n - h v_n)ᵀ M (x - x_n - h v_n) + 1/(2h) (x - x_n)ᵀ D (x - x_n)
///    by Newton (the inertia and viscosity terms are QuadraticEnergy terms of the objective),
///    v_{n+1} = (x_{n+1} - x_n) / h; the step is halved on failure (no convergence, inverted
///    element) and grows after easy steps up to max_time_step;
///  - quasistatic: the same without inertia;
///  - explicit central differences in the reduced coordinates q with the lumped mass M_q = Jᵀ M J
///    and a fixed step (a safety fraction of the critical step), damping lagged half a step.

#include <functional>
#include <string>

#include "sinew/fem/quadratic_energy.hpp"
#include "sinew/solver/newton.hpp"
#include "sinew/solver/solver_config.hpp"

namespace sinew::solver {

/// One accepted time step.
struct TimeStepRecord {
  int step = 0;               ///< accepted steps so far, this one included
  double time = 0;            ///< at the end of the step
  double step_size = 0;       ///< h
  int newton_iterations = 0;  ///< 0 for explicit
  double residual = 0;        ///< final |g_q| (implicit)
  int cuts = 0;               ///< step halvings so far (whole run)
};

struct DynamicCallbacks {
  /// Every Newton iteration (implicit integrators); `step` describes the step being attempted.
  std::function<void(const TimeStepRecord& step, const IterationRecord& iteration)> on_iteration;
  /// The initial state (step 0) and every accepted step: positions and nodal velocities (#V x 3).
  /// Explicit integration calls it about 50 times per output interval (and at output times).
  std::function<void(const TimeStepRecord& step, const fem::State& state, const NodalVectors& velocity)> on_step;
  /// At t = 0 and at every output time (multiples of output_interval, and end_time).
  std::function<void(int output, const TimeStepRecord& step, const fem::State& state, const NodalVectors& velocity)>
      on_output;
  /// A step failed and will be retried smaller.
  std::function<void(const TimeStepRecord& step, const std::string& why)> on_cut;
};

/// The terms the integrator drives (owned elsewhere; they must also be terms of the objective,
/// except for the explicit integrator, which uses them directly).
struct DynamicTerms {
  fem::QuadraticEnergy* inertia = nullptr;    ///< A = M; null for quasistatic
  fem::QuadraticEnergy* viscosity = nullptr;  ///< A = D; null without damping
};

struct DynamicSetup {
  double characteristic_length = 1;  ///< see NewtonContext
  double reference_force = 0;        ///< see NewtonContext
  double critical_time_step = 0;     ///< explicit: 2 / ω_max (time); required > 0
  NodalVectors initial_velocity;     ///< #V x 3, or empty for rest
};

struct DynamicResult {
  bool success = false;
  std::string message;  ///< what failed, when, and what to try
  fem::State last_state;
  NodalVectors last_velocity;
  double time = 0;      ///< simulated time reached
  int steps = 0;
  int newton_iterations = 0;
  int cuts = 0;
  int outputs = 0;
  double min_step = 0, max_step = 0;  ///< of the accepted steps
  PhaseTimes times;
};

DynamicResult solve_dynamic(Objective& objective, const DynamicTerms& terms, const DynamicOptions& options,
                            const StaticSolverOptions& newton_options, const DynamicSetup& setup,
                            const DynamicCallbacks& callbacks = {});

}  // namespace sinew::solver
