#pragma once
/// @file static_solver.hpp
/// Adaptive incremental loading (paper section 3.2): the load parameter lambda goes from 0 to 1
/// in user-visible increments; each increment is reached in one or more load steps whose size
/// halves when Newton fails and grows after easy steps; each step starts from a predictor
/// (the seed's two-point extrapolation, or a tangent predictor).

#include <functional>
#include <string>

#include "sinew/solver/newton.hpp"

namespace sinew::solver {

/// One accepted (or attempted) load step.
struct StepRecord {
  int increment = 0;        ///< user-visible increment this step belongs to (1-based)
  int step = 0;             ///< accepted steps so far, this one included
  double lambda = 0;        ///< load parameter at the end of the step
  double step_size = 0;     ///< its delta lambda
  int newton_iterations = 0;
  double residual = 0;      ///< final |g_q|
  double force_scale = 0;
  double energy = 0;
  int cuts = 0;             ///< step halvings so far (whole run)
  bool snap_through = false;  ///< attempted with the snap-through Newton budget
};

struct StaticCallbacks {
  /// Every Newton iteration; `step` describes the step being attempted.
  std::function<void(const StepRecord& step, const IterationRecord& iteration)> on_iteration;
  /// Every accepted step.
  std::function<void(const StepRecord& step, const fem::State& state)> on_step;
  /// After the initial equilibrium (increment 0) and after each completed increment.
  std::function<void(int increment, const fem::State& state)> on_increment;
  /// A step failed and will be retried smaller.
  std::function<void(const StepRecord& step, const std::string& why)> on_cut;
};

struct StaticSetup {
  double characteristic_length = 1;  ///< length scale of the increment criterion
  double reference_force = 0;        ///< see NewtonContext::reference_force
  VectorX node_viscosity;            ///< quasi-viscosity per node, or empty
};

struct StaticResult {
  bool success = false;
  std::string message;              ///< what failed, where, and what to try
  fem::State last_converged;
  int increments_completed = 0;
  int steps = 0;
  int newton_iterations = 0;
  int cuts = 0;
  int snap_throughs = 0;  ///< steps solved with the snap-through budget (LoadSteppingOptions)
  PhaseTimes times;
};

StaticResult solve_static(Objective& objective, const StaticSolverOptions& options, const StaticSetup& setup,
                          const StaticCallbacks& callbacks = {});

}  // namespace sinew::solver
