#include "sinew/solver/dynamic_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "sinew/core/error.hpp"
#include "sinew/solver/linear_solver.hpp"
#include "sinew/solver/prescribed_turn.hpp"

namespace sinew::solver {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// Multiples of the output interval, the last one exactly end_time.
struct OutputClock {
  double interval, end;
  int next = 1;
  double time() const { return std::min(end, next * interval); }
  /// True (and advances) when t reached the next output time (within round-off).
  bool reached(double t) {
    if (t < time() - 1e-9 * interval) return false;
    ++next;
    return true;
  }
};

void check_options(const DynamicOptions& o) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (!positive(o.end_time)) throw std::invalid_argument(fmt::format("dynamics: end_time must be > 0, got {}", o.end_time));
  if (!positive(o.output_interval))
    throw std::invalid_argument(fmt::format("dynamics: output_interval must be > 0, got {}", o.output_interval));
  if (!(o.explicit_safety > 0 && o.explicit_safety <= 1))
    throw std::invalid_argument(fmt::format("dynamics: explicit_safety must be in (0, 1], got {}", o.explicit_safety));
}

DynamicResult solve_implicit(Objective& objective, const DynamicTerms& terms, const DynamicOptions& options,
                             const StaticSolverOptions& solver_options, const DynamicSetup& setup,
                             const DynamicCallbacks& callbacks) {
  const fem::DofMap& dofs = objective.dofs();
  const bool with_inertia = options.integrator == DynamicOptions::Integrator::ImplicitEuler;
  if (with_inertia && !terms.inertia) throw std::invalid_argument("solve_dynamic: implicit Euler needs an inertia term");
  DynamicResult result;
  auto linear = make_linear_solver(solver_options.linear);
  fem::SparseMatrix K;

  const double T = options.end_time;
  const double max_step = options.max_time_step > 0 ? options.max_time_step : options.output_interval;
  double dt = std::min(max_step, options.time_step > 0 ? options.time_step : options.output_interval / 10);
  const double min_step = options.min_time_step > 0 ? options.min_time_step : 1e-6 * dt;

  NewtonContext context;
  context.characteristic_length = setup.characteristic_length;
  context.reference_force = setup.reference_force;
  if (with_inertia && terms.inertia) context.transient_terms.push_back(terms.inertia);
  if (terms.viscosity) context.transient_terms.push_back(terms.viscosity);
  TimeStepRecord attempt;
  context.on_iteration = [&](const IterationRecord& it) {
    if (callbacks.on_iteration) callbacks.on_iteration(attempt, it);
  };

  fem::State current = dofs.initial_state(0.0);
  NodalVectors velocity = setup.initial_velocity.size() > 0 ? setup.initial_velocity
                                                             : NodalVectors::Zero(current.x.rows(), 3);
  TimeStepRecord record;
  if (callbacks.on_step) callbacks.on_step(record, current, velocity);
  if (callbacks.on_output) callbacks.on_output(result.outputs, record, current, velocity);
  ++result.outputs;
  OutputClock outputs{options.output_interval, T};
  double t = 0;
  result.min_step = std::numeric_limits<double>::infinity();
  while (t < T * (1 - 1e-12)) {
    // A large prescribed rotation is taken in several steps (see prescribed_turn.hpp).
    const double h = T * step_within_turn_bound(dofs, t / T, std::min(dt, outputs.time() - t) / T, min_step / T);
    if (h < min_step) {
      result.message = fmt::format(
          "a prescribed motion turns by more than {:.0f} degrees within the smallest allowed time step from "
          "t = {:.6g} (min_time_step {:.3g}): slow the rotation down (a longer end_time) or allow smaller steps",
          kMaxPrescribedTurnPerStep * 180 / std::numbers::pi, t, min_step);
      break;
    }
    attempt = record;
    attempt.time = t + h;
    attempt.step_size = h;
    fem::State trial = current;
    const double lambda = std::min(1.0, (t + h) / T);
    dofs.sync(trial, lambda);
    objective.set_load_parameter(lambda);
    if (with_inertia) terms.inertia->set_center_and_scale(current.x + h * velocity, 1.0 / (h * h));
    if (terms.viscosity) terms.viscosity->set_center_and_scale(current.x, 1.0 / h);
    objective.begin_step(trial);
    const NewtonResult newton =
        newton_solve(objective, trial, solver_options.newton, *linear, K, context, result.times);
    result.newton_iterations += newton.iterations;
    if (!newton.converged) {
      ++result.cuts;
      attempt.cuts = result.cuts;
      if (callbacks.on_cut) callbacks.on_cut(attempt, newton.failure);
      dt = h / 2;
      if (dt < min_step) {
        result.message = fmt::format(
            "the time step from t = {:.6g} could not be solved even with h = {:.3g} (min_time_step {:.3g}): {}. "
            "The last converged state (t = {:.6g}) is kept. Try a smaller time_step or more damping.",
            t, h, min_step, newton.failure, t);
        break;
      }
      continue;
    }
    velocity = (trial.x - current.x) / h;
    current = std::move(trial);
    t = h == outputs.time() - t ? outputs.time() : t + h;  // land exactly on output times
    ++result.steps;
    result.min_step = std::min(result.min_step, h);
    result.max_step = std::max(result.max_step, h);
    record.step = result.steps;
    record.time = t;
    record.step_size = h;
    record.newton_iterations = newton.iterations;
    record.residual = newton.residual;
    record.cuts = result.cuts;
    if (callbacks.on_step) callbacks.on_step(record, current, velocity);
    if (outputs.reached(t)) {
      if (callbacks.on_output) callbacks.on_output(result.outputs, record, current, velocity);
      ++result.outputs;
    }
    // Grow after an easy step (and after a step shortened only to land on an output time).
    if (newton.iterations <= options.easy_iterations && h >= dt * (1 - 1e-12))
      dt = std::min(max_step, dt * options.growth);
  }
  result.success = result.message.empty();
  result.time = t;
  if (result.success)
    result.message = fmt::format("solved: t = {:.6g} in {} time steps, {} Newton iterations, {} cuts", t,
                                 result.steps, result.newton_iterations, result.cuts);
  result.last_state = std::move(current);
  result.last_velocity = std::move(velocity);
  if (result.steps == 0) result.min_step = 0;
  return result;
}

DynamicResult solve_explicit(Objective& objective, const DynamicTerms& terms, const DynamicOptions& options,
                             const DynamicSetup& setup, const DynamicCallbacks& callbacks) {
  if (!terms.inertia) throw std::invalid_argument("solve_dynamic: explicit integration needs the (lumped) mass");
  if (!(setup.critical_time_step > 0) || !std::isfinite(setup.critical_time_step))
    throw std::invalid_argument("solve_dynamic: explicit integration needs the critical time step (> 0)");
  DynamicResult result;
  const double T = options.end_time;
  const double dt = options.explicit_safety * setup.critical_time_step;

  // Reduced mass M_q = Jᵀ M J with its own copy of the DofMap (the objective's one is bound to
  // the objective's Hessian pattern).
  fem::DofMap mass_dofs = objective.dofs();
  const BlockSparseMatrix& M = terms.inertia->matrix();
  mass_dofs.bind_pattern(M);
  fem::SparseMatrix Mq;
  auto linear = make_linear_solver(LinearSolverOptions{});
  bool diagonal = false;
  VectorX inverse_diagonal;
  const NodalVectors no_gradient = NodalVectors::Zero(M.num_nodes(), 3);
  auto factor_mass = [&](const fem::State& state, bool first) {
    mass_dofs.reduce_hessian(state, M, no_gradient, VectorX(), Mq);
    diagonal = Mq.nonZeros() == Mq.rows();
    if (diagonal) {
      inverse_diagonal = Mq.diagonal().cwiseInverse();
      if (!inverse_diagonal.allFinite())
        throw InputError("explicit integration: a degree of freedom has no mass (a region or rigid body of density 0?): give every moving part a density > 0");
      return;
    }
    if (first) linear->analyze(Mq);
    if (!linear->factorize(Mq))
      throw InputError("explicit integration: the reduced mass matrix is singular (a region or rigid body of density 0?): give every moving part a density > 0");
  };
  bool rigid_free = false;
  for (Index a = 0; a < M.num_nodes(); ++a)
    if (objective.dofs().kind(a) == fem::DofMap::NodeKind::RigidMember) rigid_free = true;

  fem::State current = objective.dofs().initial_state(0.0);
  const fem::DofMap& dofs = objective.dofs();
  factor_mass(current, true);
  auto solve_mass = [&](const VectorX& rhs) {
    if (diagonal) return VectorX(inverse_diagonal.cwiseProduct(rhs));
    VectorX out;
    linear->solve(rhs, out);
    return out;
  };
  // Reduced velocity from nodal initial velocities: v_q = M_q^-1 Jᵀ M v.
  VectorX vq = VectorX::Zero(dofs.num_dofs());
  if (setup.initial_velocity.size() > 0)
    vq = solve_mass(dofs.reduce_gradient(current, terms.inertia->multiply(setup.initial_velocity)));
  auto nodal_velocity = [&](const fem::State& state, const VectorX& v) {
    const fem::State moved = dofs.apply_step(state, v, dt);
    return NodalVectors((moved.x - state.x) / dt);
  };
  objective.set_load_parameter(0.0);
  objective.begin_step(current);
  auto acceleration = [&](const fem::State& state, const NodalVectors& velocity_full) {
    std::optional<PhaseTimer> forces_timer(std::in_place, result.times.forces_and_stiffness, objective);
    NodalVectors g = objective.full_gradient(state);
    if (terms.viscosity) g += terms.viscosity->multiply(velocity_full);
    const VectorX gq = dofs.reduce_gradient(state, g);
    forces_timer.reset();
    const auto t0 = Clock::now();
    VectorX a = -solve_mass(gq);
    result.times.linear_solve += seconds_since(t0);
    return a;
  };
  if (!objective.is_valid(current)) {
    result.message = "explicit integration: the initial state is not admissible (inverted element?)";
    return result;
  }
  NodalVectors v_full = nodal_velocity(current, vq);
  VectorX a = acceleration(current, v_full);
  TimeStepRecord record;
  record.step_size = dt;
  if (callbacks.on_step) callbacks.on_step(record, current, v_full);
  if (callbacks.on_output) callbacks.on_output(result.outputs, record, current, v_full);
  ++result.outputs;
  OutputClock outputs{options.output_interval, T};
  const int log_every = std::max(1, static_cast<int>(options.output_interval / dt / 50));
  double t = 0;
  result.min_step = dt;
  result.max_step = dt;
  while (t < T * (1 - 1e-12)) {
    const double h = std::min(dt, outputs.time() - t);
    // Kick-drift-kick (velocity Verlet = central differences): v_{n+1/2} = v_n + h/2 a_n.
    const VectorX v_half = vq + 0.5 * h * a;
    fem::State next = dofs.apply_step(current, v_half, h);
    const double lambda = std::min(1.0, (t + h) / T);
    dofs.sync(next, lambda);
    objective.set_load_parameter(lambda);
    if (options.explicit_rebuild_every > 0 && (result.steps + 1) % options.explicit_rebuild_every == 0) {
      objective.begin_step(next);
    }
    if (!objective.is_valid(next)) {
      result.message = fmt::format(
          "explicit integration: an element inverted at t = {:.6g} (step {}, h = {:.3g}); if the motion is one a solid "
          "can follow, lower explicit_safety "
          "(now {}) or use the implicit integrator",
          t + h, result.steps + 1, h, options.explicit_safety);
      break;
    }
    if (rigid_free) factor_mass(next, false);
    v_full = (next.x - current.x) / h;
    const VectorX a_next = acceleration(next, v_full);
    vq = v_half + 0.5 * h * a_next;
    a = a_next;
    current = std::move(next);
    t = h == outputs.time() - t ? outputs.time() : t + h;  // land exactly on output times
    ++result.steps;
    result.min_step = std::min(result.min_step, h);
    record.step = result.steps;
    record.time = t;
    record.step_size = h;
    const bool output_now = outputs.reached(t);
    // Thousands of steps: on_step (the per-step log) about 50 times per output interval.
    const bool log_now = output_now || result.steps % log_every == 0;
    if ((callbacks.on_step && log_now) || output_now) v_full = nodal_velocity(current, vq);
    if (callbacks.on_step && log_now) callbacks.on_step(record, current, v_full);
    if (output_now) {
      if (callbacks.on_output) callbacks.on_output(result.outputs, record, current, v_full);
      ++result.outputs;
    }
  }
  result.success = result.message.empty();
  result.time = t;
  if (result.success) result.message = fmt::format("solved: t = {:.6g} in {} explicit steps", t, result.steps);
  result.last_state = std::move(current);
  result.last_velocity = nodal_velocity(result.last_state, vq);
  return result;
}

}  // namespace

DynamicResult solve_dynamic(Objective& objective, const DynamicTerms& terms, const DynamicOptions& options,
                            const StaticSolverOptions& newton_options, const DynamicSetup& setup,
                            const DynamicCallbacks& callbacks) {
  check_options(options);
  const double collision_before = objective.collision_seconds();
  DynamicResult result = options.integrator == DynamicOptions::Integrator::Explicit
                              ? solve_explicit(objective, terms, options, setup, callbacks)
                              : solve_implicit(objective, terms, options, newton_options, setup, callbacks);
  result.times.collision = objective.collision_seconds() - collision_before;
  return result;
}

}  // namespace sinew::solver
