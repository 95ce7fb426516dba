#include "sinew/solver/static_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "sinew/solver/prescribed_turn.hpp"

namespace sinew::solver {
namespace {

using Predictor = LoadSteppingOptions::Predictor;

/// First-order predictor: dq = -K^-1 (dg/dlambda) dlambda, with dg/dlambda from a forward
/// difference of the gradient under the prescribed motion and loads alone.
fem::State tangent_prediction(Objective& objective, const fem::State& converged, double lambda_new,
                              LinearSolver& linear, fem::SparseMatrix& K, bool& linear_ready,
                              const StaticSetup& setup, PhaseTimes& times) {
  const fem::DofMap& dofs = objective.dofs();
  const double lambda0 = converged.lambda;
  const double h = 1e-6 * std::max(1.0, std::abs(lambda0));
  std::optional<PhaseTimer> forces_timer(std::in_place, times.forces_and_stiffness, objective);
  objective.set_load_parameter(lambda0);
  const NodalVectors g0_full = objective.full_gradient(converged);
  const VectorX g0 = dofs.reduce_gradient(converged, g0_full);
  if (!linear_ready) {
    const bool fresh = objective.hessian(converged, g0_full, setup.node_viscosity, K);
    if (fresh) linear.analyze(K);
    linear_ready = linear.factorize(K);
  }
  fem::State nudged = converged;
  dofs.sync(nudged, lambda0 + h);
  objective.set_load_parameter(lambda0 + h);
  const VectorX gh = dofs.reduce_gradient(nudged, objective.full_gradient(nudged));
  objective.set_load_parameter(lambda_new);
  forces_timer.reset();

  fem::State base = converged;
  dofs.sync(base, lambda_new);
  if (!linear_ready) return base;
  const auto t0 = std::chrono::steady_clock::now();
  VectorX dq;
  const LinearSolveStats stats = linear.solve(-(gh - g0) / h * (lambda_new - lambda0), dq);
  times.linear_solve += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!stats.success) return base;
  return dofs.apply_step(base, dq, 1.0);
}

StaticResult solve_load_steps(Objective& objective, const StaticSolverOptions& options, const StaticSetup& setup,
                              const StaticCallbacks& callbacks) {
  const fem::DofMap& dofs = objective.dofs();
  const LoadSteppingOptions& stepping = options.stepping;
  StaticResult result;
  auto linear = make_linear_solver(options.linear);
  fem::SparseMatrix K;
  bool linear_ready = false;

  NewtonContext context;
  context.characteristic_length = setup.characteristic_length;
  context.node_viscosity = setup.node_viscosity;
  context.reference_force = setup.reference_force;
  StepRecord attempt;
  context.on_iteration = [&](const IterationRecord& it) {
    if (it.iteration > 0) linear_ready = true;
    if (callbacks.on_iteration) callbacks.on_iteration(attempt, it);
  };

  // Equilibrium at lambda = 0 (a stress-free rest state converges at once).
  fem::State current = dofs.initial_state(0.0);
  objective.set_load_parameter(0.0);
  objective.begin_step(current);
  {
    // The initial state may start deeply interpenetrated (contact pushes it apart): a larger budget.
    NewtonOptions initial = options.newton;
    initial.max_iterations = std::max(4 * initial.max_iterations, 100);
    const NewtonResult newton = newton_solve(objective, current, initial, *linear, K, context, result.times);
    result.newton_iterations += newton.iterations;
    if (!newton.converged) {
      result.message = fmt::format("the initial state (lambda = 0) has no equilibrium the solver could find: {}",
                                   newton.failure);
      result.last_converged = dofs.initial_state(0.0);
      return result;
    }
  }
  result.last_converged = current;
  if (callbacks.on_increment) callbacks.on_increment(0, current);

  const int increments = std::max(1, stepping.increments);
  const double increment_size = 1.0 / increments;
  double step = increment_size;
  fem::State previous;
  bool has_previous = false;
  int failures_in_a_row = 0;  // attempts failed since the last converged step

  for (int k = 1; k <= increments; ++k) {
    const double target = (k == increments) ? 1.0 : k * increment_size;
    while (current.lambda < target - 1e-12 * increment_size) {
      double delta = std::min(step, target - current.lambda);
      if (target - (current.lambda + delta) < 1e-6 * increment_size) delta = target - current.lambda;
      // A large prescribed rotation is taken in several steps (a turn of 360 degrees in one
      // step would land on the rest pose).
      const double smallest = stepping.min_step * increment_size;
      delta = step_within_turn_bound(dofs, current.lambda, delta, smallest);
      if (delta < smallest) {
        result.message = fmt::format(
            "a prescribed motion turns by more than {:.0f} degrees within the smallest allowed load step from "
            "lambda = {:.6g} ({:.3g}, min_step = {:.3g} of an increment): give the rotation fewer degrees per "
            "increment (more increments) or a larger min_step",
            kMaxPrescribedTurnPerStep * 180 / std::numbers::pi, current.lambda, smallest, stepping.min_step);
        return result;
      }
      const double lambda_new = current.lambda + delta;
      attempt = StepRecord{};
      attempt.increment = k;
      attempt.step = result.steps + 1;
      attempt.lambda = lambda_new;
      attempt.step_size = delta;
      attempt.cuts = result.cuts;

      // Predictor.
      objective.begin_step(current);
      fem::State trial;
      if (stepping.predictor == Predictor::Tangent) {
        trial = tangent_prediction(objective, current, lambda_new, *linear, K, linear_ready, setup, result.times);
      } else if (stepping.predictor == Predictor::TwoPoint && has_previous) {
        trial = dofs.extrapolate(previous, current, delta / (current.lambda - previous.lambda), lambda_new);
      } else {
        trial = current;
        dofs.sync(trial, lambda_new);
      }
      objective.set_load_parameter(lambda_new);
      if (!objective.is_valid(trial)) {
        trial = current;
        dofs.sync(trial, lambda_new);
      }

      NewtonOptions newton_options = options.newton;
      const bool snap_attempt = stepping.snap_through_after_cuts > 0 &&
                                failures_in_a_row == stepping.snap_through_after_cuts;
      attempt.snap_through = snap_attempt;
      if (snap_attempt)
        newton_options.max_iterations = std::max(newton_options.max_iterations, stepping.snap_through_iterations);
      const NewtonResult newton = newton_solve(objective, trial, newton_options, *linear, K, context, result.times);
      result.newton_iterations += newton.iterations;
      if (newton.converged) {
        failures_in_a_row = 0;
        if (snap_attempt) ++result.snap_throughs;
        previous = std::move(current);
        has_previous = true;
        current = std::move(trial);
        ++result.steps;
        attempt.newton_iterations = newton.iterations;
        attempt.residual = newton.residual;
        attempt.force_scale = newton.force_scale;
        attempt.energy = newton.energy;
        result.last_converged = current;
        if (callbacks.on_step) callbacks.on_step(attempt, current);
        if (newton.iterations <= stepping.easy_iterations) step = std::min(step * stepping.growth, increment_size);
        continue;
      }
      ++result.cuts;
      ++failures_in_a_row;
      attempt.cuts = result.cuts;
      if (callbacks.on_cut) callbacks.on_cut(attempt, newton.failure);
      step = delta / 2;
      objective.set_load_parameter(current.lambda);
      if (step < stepping.min_step * increment_size) {
        result.message = fmt::format(
            "load step from lambda = {:.6g} could not be solved even with a step of {:.3g} (the smallest allowed is "
            "{:.3g}, min_step = {:.3g} of an increment): {}. The last converged state (lambda = {:.6g}) is kept. Try "
            "more increments, quasi-viscosity, or check that the prescribed motion is physically possible.",
            current.lambda, delta, stepping.min_step * increment_size, stepping.min_step, newton.failure,
            current.lambda);
        return result;
      }
    }
    result.increments_completed = k;
    if (callbacks.on_increment) callbacks.on_increment(k, current);
  }
  result.success = true;
  result.message = fmt::format("solved: {} increments, {} steps, {} Newton iterations, {} step cuts{}", increments,
                               result.steps, result.newton_iterations, result.cuts,
                               result.snap_throughs > 0
                                   ? fmt::format(", {} snap-through{}", result.snap_throughs,
                                                 result.snap_throughs == 1 ? "" : "s")
                                   : "");
  return result;
}

}  // namespace

StaticResult solve_static(Objective& objective, const StaticSolverOptions& options, const StaticSetup& setup,
                          const StaticCallbacks& callbacks) {
  const double collision_before = objective.collision_seconds();
  StaticResult result = solve_load_steps(objective, options, setup, callbacks);
  result.times.collision = objective.collision_seconds() - collision_before;
  return result;
}

}  // namespace sinew::solver
