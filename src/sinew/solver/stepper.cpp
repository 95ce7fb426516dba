#include "sinew/solver/stepper.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sinew::solver {

StepCounts counts_of(const StepperResult& result) {
  return {result.segments_completed, result.steps,      result.newton_iterations, result.cuts,
          result.snap_throughs,      result.refinements, result.min_step,          result.max_step,
          result.stabilized_steps,   result.dissipated};
}

StepperResult run_stepper(NewtonSolver& newton, StepScheme& scheme, const StepperOptions& options,
                          const StepperCallbacks& callbacks, StepRefinement* refinement) {
  Objective& objective = newton.objective();
  const double collision_before = objective.collision_seconds();
  const PhaseTimes times_before = newton.times();
  const LinearCounts counts_before = newton.counts();
  StepperResult result;
  auto times_so_far = [&] {
    PhaseTimes times = newton.times();
    times.forces_and_stiffness -= times_before.forces_and_stiffness;
    times.linear_solve -= times_before.linear_solve;
    times.line_search -= times_before.line_search;
    times.other -= times_before.other;
    times.collision = objective.collision_seconds() - collision_before;
    return times;
  };
  auto linear_so_far = [&] {
    return LinearCounts{.factorizations = newton.counts().factorizations - counts_before.factorizations,
                        .linear_iterations = newton.counts().linear_iterations - counts_before.linear_iterations,
                        .undone_lagged_steps =
                            newton.counts().undone_lagged_steps - counts_before.undone_lagged_steps};
  };
  auto finish = [&](StepperResult& r) -> StepperResult& {
    r.times = times_so_far();
    r.linear = linear_so_far();
    if (r.steps == 0) r.min_step = 0;
    r.last_velocity = scheme.velocity();
    return r;
  };

  StepRecord attempt;
  auto on_iteration = [&](const IterationRecord& it) {
    if (callbacks.on_iteration) callbacks.on_iteration(attempt, it);
  };

  const double segment_length = options.segment_length > 0 ? options.segment_length : options.end;
  const int segments = std::max(1, static_cast<int>(std::ceil(options.end / segment_length * (1 - 1e-12))));
  double step = std::min(options.first_step, options.max_step);
  int failures_in_a_row = 0;  // attempts failed since the last converged step
  bool stabilizing = false;   // StepScheme::start_stabilizing was called (it stays on)
  double t = 0;
  int first_segment = 1;
  StepRecord record;
  fem::State current;
  result.min_step = std::numeric_limits<double>::infinity();

  if (const StepperSnapshot* snapshot = options.resume) {
    current = snapshot->state;
    scheme.restore(current, snapshot->scheme);
    t = snapshot->t;
    step = snapshot->next_step;
    record = snapshot->record;
    const StepCounts& c = snapshot->counts;
    result.segments_completed = c.segments_completed;
    result.steps = c.steps;
    result.newton_iterations = c.newton_iterations;
    result.cuts = c.cuts;
    result.snap_throughs = c.snap_throughs;
    result.refinements = c.refinements;
    result.stabilized_steps = c.stabilized_steps;
    result.dissipated = c.dissipated;
    stabilizing = snapshot->scheme.stabilized;
    if (c.steps > 0) result.min_step = c.min_step;
    result.max_step = c.max_step;
    result.t = t;
    first_segment = snapshot->segment_done ? snapshot->segment + 1 : snapshot->segment;
  } else {
    current = scheme.start();
    const StepRecord start_record;
    if (options.start == StepperOptions::Start::SolveEquilibrium) {
      // The start may be deeply interpenetrated (contact pushes it apart): a larger budget.
      NewtonOptions initial = options.newton;
      initial.max_iterations = std::max(4 * initial.max_iterations, 100);
      fem::State unsolved = current;
      const NewtonResult solved = newton.solve(current, initial, on_iteration);
      result.newton_iterations += solved.iterations;
      if (!solved.converged) {
        result.message = scheme.start_failed(solved.failure);
        result.last_state = std::move(unsolved);
        return finish(result);
      }
    } else if (callbacks.on_step) {
      callbacks.on_step(start_record, current, scheme.velocity());
    }
    if (callbacks.on_segment) callbacks.on_segment(0, start_record, current, scheme.velocity());
  }
  result.last_state = current;

  // Ends segment k at the last accepted step (once).
  auto complete_segment = [&](int k) {
    if (result.segments_completed >= k) return;
    result.segments_completed = k;
    if (callbacks.on_segment) callbacks.on_segment(k, record, current, scheme.velocity());
  };

  for (int k = first_segment; k <= segments; ++k) {
    const double target = k == segments ? options.end : std::min(options.end, k * segment_length);
    while (t < target - 1e-12 * segment_length) {
      double h = std::min(step, target - t);
      if (target - (t + h) < options.snap_to_segment_end * segment_length) h = target - t;
      // A large prescribed rotation is taken in several steps (prescribed_turn.hpp).
      h = scheme.bound_step(t, h, options.min_step);
      if (h < options.min_step) {
        result.message = scheme.turn_too_fast(t, options.min_step);
        result.t = t;
        return finish(result);
      }
      const double t_new = h == target - t ? target : t + h;
      attempt = StepRecord{};
      attempt.segment = k;
      attempt.step = result.steps + 1;
      attempt.t = t_new;
      attempt.step_size = h;
      attempt.cuts = result.cuts;

      fem::State trial = scheme.predict(current, t, t_new, newton);
      NewtonOptions newton_options = options.newton;
      const bool snap_attempt =
          options.snap_through_after_cuts > 0 && failures_in_a_row == options.snap_through_after_cuts;
      attempt.snap_through = snap_attempt;
      if (snap_attempt)
        newton_options.max_iterations = std::max(newton_options.max_iterations, options.snap_through_iterations);
      NewtonResult solved = newton.solve(trial, newton_options, on_iteration);
      result.newton_iterations += solved.iterations;
      int iterations = solved.iterations;
      // The refinement's outer iterations: solve the step again from its converged state. A
      // re-solve that fails goes back to that state for a smaller change of the objective, or
      // keeps it when there is none.
      while (solved.converged && refinement && refinement->refine(trial)) {
        const fem::State converged_state = trial;
        const NewtonResult converged_solve = solved;
        do {
          ++attempt.refinements;
          solved = newton.solve(trial, newton_options, on_iteration);
          result.newton_iterations += solved.iterations;
          iterations += solved.iterations;
          if (solved.converged) break;
          trial = converged_state;
        } while (refinement->retry_softer());
        if (!solved.converged) solved = converged_solve;
      }
      if (solved.converged) {
        if (refinement) refinement->accept(trial);
        result.refinements += attempt.refinements;
        failures_in_a_row = 0;
        if (snap_attempt) ++result.snap_throughs;
        scheme.accept(current, trial, h);
        current = std::move(trial);
        t = t_new;
        ++result.steps;
        result.min_step = std::min(result.min_step, h);
        result.max_step = std::max(result.max_step, h);
        record = attempt;
        record.newton_iterations = iterations;
        record.residual = solved.residual;
        record.force_scale = solved.force_scale;
        record.dissipated = scheme.last_dissipation();
        // The stabilization's term is part of Newton's objective; the step's energy is without it.
        record.energy = solved.energy - 0.5 * record.dissipated;
        if (stabilizing) {
          ++result.stabilized_steps;
          result.dissipated += record.dissipated;
        }
        result.last_state = current;
        result.t = t;
        if (callbacks.on_step) callbacks.on_step(record, current, scheme.velocity());
        const bool easy = iterations <= options.easy_iterations;
        const bool full = options.growth_rule == StepperOptions::Growth::AfterEasyStep || h >= step * (1 - 1e-12);
        if (easy && full) step = std::min(step * options.growth, options.max_step);
        const bool segment_done = !(t < target - 1e-12 * segment_length);
        if (segment_done) complete_segment(k);
        if (callbacks.on_accepted) {
          StepperSnapshot snapshot;
          snapshot.state = current;
          snapshot.t = t;
          snapshot.next_step = step;
          snapshot.segment = k;
          snapshot.segment_done = segment_done;
          snapshot.record = record;
          snapshot.counts = counts_of(result);
          snapshot.scheme = scheme.memory(current, newton);
          snapshot.times = times_so_far();
          snapshot.linear = linear_so_far();
          callbacks.on_accepted(snapshot);
        }
        continue;
      }
      if (refinement) refinement->reject();
      ++result.cuts;
      ++failures_in_a_row;
      attempt.cuts = result.cuts;
      if (callbacks.on_cut) callbacks.on_cut(attempt, solved.failure);
      step = h / 2;
      scheme.reject(current);
      if (step < options.min_step && !stabilizing && scheme.start_stabilizing()) {
        // Stuck: go on stabilized (it stays on for the rest of the run), from a step that the
        // damping may make solvable again; smaller ones follow by halving.
        stabilizing = true;
        failures_in_a_row = 0;
        step = std::max(h, options.stabilized_step);
        if (callbacks.on_stabilize) callbacks.on_stabilize(attempt, solved.failure);
        continue;
      }
      if (step < options.min_step) {
        result.message = scheme.step_too_small(t, h, options.min_step, solved.failure);
        result.t = t;
        return finish(result);
      }
    }
    complete_segment(k);
  }
  result.success = true;
  result.t = t;
  result.message = scheme.solved(result);
  return finish(result);
}

}  // namespace sinew::solver
