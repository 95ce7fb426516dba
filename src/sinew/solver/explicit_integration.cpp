#include "sinew/solver/explicit_integration.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "sinew/core/error.hpp"
#include "sinew/core/stopwatch.hpp"
#include "sinew/fem/hessian_reduction.hpp"
#include "sinew/solver/linear_solver.hpp"

namespace sinew::solver {
namespace {

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

}  // namespace

StepperResult solve_explicit(Objective& objective, const DynamicTerms& terms, const DynamicOptions& options,
                             const DynamicSetup& setup, const StepperCallbacks& callbacks) {
  if (!terms.inertia) throw InputError("explicit integration needs the (lumped) mass matrix");
  if (!(setup.critical_time_step > 0) || !std::isfinite(setup.critical_time_step))
    throw InputError("explicit integration needs the critical time step (> 0)");
  StepperResult result;
  const double collision_before = objective.collision_seconds();
  const double T = options.end_time;
  const double dt = options.explicit_safety * setup.critical_time_step;

  // Reduced mass M_q = Jᵀ M J with its own q-space pattern (M's, not the objective's Hessian's).
  fem::HessianReduction mass_reduction(objective.dofs());
  const BlockSparseMatrix& M = terms.inertia->matrix();
  mass_reduction.bind(M);
  fem::SparseMatrix Mq;
  auto linear = make_linear_solver(LinearSolverOptions{});
  bool diagonal = false;
  VectorX inverse_diagonal;
  const NodalVectors no_gradient = NodalVectors::Zero(M.num_nodes(), 3);
  auto factor_mass = [&](const fem::State& state, bool first) {
    mass_reduction.reduce(state, M, no_gradient, VectorX(), Mq);
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
    const auto t0 = std::chrono::steady_clock::now();
    VectorX a = -solve_mass(gq);
    result.times.linear_solve += seconds_since(t0);
    return a;
  };
  if (!objective.is_valid(current)) {
    result.message = "explicit integration: the initial state is not admissible (inverted element?)";
    result.last_state = current;
    return result;
  }
  NodalVectors v_full = nodal_velocity(current, vq);
  VectorX a = acceleration(current, v_full);
  StepRecord record;
  record.step_size = dt;
  if (callbacks.on_step) callbacks.on_step(record, current, v_full);
  if (callbacks.on_segment) callbacks.on_segment(0, record, current, v_full);
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
    record.t = t;
    record.step_size = h;
    const bool output_now = outputs.reached(t);
    // Thousands of steps: on_step (the per-step log) about 50 times per output interval.
    const bool log_now = output_now || result.steps % log_every == 0;
    if ((callbacks.on_step && log_now) || output_now) v_full = nodal_velocity(current, vq);
    if (callbacks.on_step && log_now) callbacks.on_step(record, current, v_full);
    if (output_now) {
      ++result.segments_completed;
      if (callbacks.on_segment) callbacks.on_segment(result.segments_completed, record, current, v_full);
    }
  }
  result.success = result.message.empty();
  result.t = t;
  if (result.success) result.message = fmt::format("solved: t = {:.6g} in {} explicit steps", t, result.steps);
  result.last_state = std::move(current);
  result.last_velocity = nodal_velocity(result.last_state, vq);
  result.times.collision = objective.collision_seconds() - collision_before;
  return result;
}

}  // namespace sinew::solver
