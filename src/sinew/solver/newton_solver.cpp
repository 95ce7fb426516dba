#include "sinew/solver/newton_solver.hpp"

#include "sinew/fem/rigid_body_modes.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "sinew/core/stopwatch.hpp"
#include "sinew/solver/newton_direction.hpp"
#include "sinew/solver/row_order.hpp"

namespace sinew::solver {

PhaseTimer::PhaseTimer(double& sink, const Objective& objective)
    : sink_(sink),
      objective_(objective),
      collision_start_(objective.collision_seconds()),
      start_(std::chrono::steady_clock::now()) {}

PhaseTimer::~PhaseTimer() {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double collision = objective_.collision_seconds() - collision_start_;
  sink_ += std::max(0.0, elapsed - collision);
}

namespace {

double largest_displacement(const fem::State& a, const fem::State& b) {
  return (a.x - b.x).rowwise().norm().maxCoeff();
}

/// |g_q| of the objective without the transient terms, from the full gradient `full_g` at `state`.
double equilibrium_residual(const fem::DofMap& dofs, const fem::State& state, const NodalVectors& full_g,
                            double residual, const std::vector<const Energy*>& transient_terms) {
  if (transient_terms.empty()) return residual;
  NodalVectors transient = NodalVectors::Zero(full_g.rows(), 3);
  for (const Energy* term : transient_terms) term->add_gradient(state.x, transient);
  return dofs.reduce_gradient(state, full_g - transient).norm();
}

/// Residuals below this fraction of the reference force are round-off.
constexpr double kRoundoffResidual = 1e-13;

}  // namespace

NewtonSolver::NewtonSolver(Objective& objective, const LinearSolverOptions& linear, NewtonSetup setup)
    : objective_(objective), linear_(make_linear_solver(linear)), setup_(std::move(setup)) {
  // A solver that adds the ranks' parts of K needs no whole K on every rank (docs/mpi.md).
  objective_.set_hessian_summed(!linear_->adds_ranks_parts());
}

bool NewtonSolver::ensure_factorization(const fem::State& state, const NodalVectors& full_gradient) {
  if (factorized_) return true;
  if (objective_.dofs().num_dofs() == 0) return false;  // everything prescribed: nothing to factorize
  bool fresh;
  {
    PhaseTimer watch(times_.forces_and_stiffness, objective_);
    fresh = objective_.hessian(state, full_gradient, setup_.node_viscosity, K_);
  }
  Stopwatch watch(times_.linear_solve);
  prepare_linear_solver(state);
  if (fresh) linear_->analyze(K_);
  factorized_ = linear_->factorize(K_);
  return factorized_;
}

void NewtonSolver::prepare_linear_solver(const fem::State& state) {
  if (!setup_.node_owner.empty() && owners_passed_for_ != objective_.dofs().num_dofs()) {
    linear_->set_row_owners(unknown_owners(objective_.dofs(), setup_.node_owner, state.x.rows()));
    owners_passed_for_ = objective_.dofs().num_dofs();
  }
  if (!linear_->wants_rigid_body_modes()) return;
  const fem::DofMap& dofs = objective_.dofs();
  // Called within the factorize() that follows, while `state` is alive.
  linear_->set_rigid_body_motions(
      [&dofs, &state](const std::vector<Index>& unknowns) { return fem::rigid_body_motions(dofs, state, unknowns); },
      fem::unknowns_block_size(dofs, state.x.rows()));
}

LinearCounts NewtonSolver::counts() const {
  LinearCounts counts;
  counts.factorizations = linear_->factorizations();
  counts.linear_iterations = linear_iterations_;
  counts.undone_lagged_steps = undone_lagged_steps_;
  return counts;
}

bool NewtonSolver::solve_with_last_factorization(const VectorX& rhs, VectorX& x) {
  if (!factorized_) return false;
  Stopwatch watch(times_.linear_solve);
  return linear_->solve(rhs, x).success;
}

double NewtonSolver::extrapolate(const fem::State& state, const VectorX& dq, double slope, double max_growth,
                                 TrialPoint& point) {
  const fem::DofMap& dofs = objective_.dofs();
  const auto compute_gradient = [&](TrialPoint& p) {
    PhaseTimer watch(times_.forces_and_stiffness, objective_);
    p.full_g = objective_.full_gradient(p.state, &p.scale);
    p.g = dofs.reduce_gradient(p.state, p.full_g);
  };
  if (point.full_g.rows() == 0) compute_gradient(point);  // needed by the next iteration anyway
  double alpha = 1;
  while (point.g.dot(dq) < kExtrapolationSlopeRatio * slope && 2 * alpha <= max_growth) {
    TrialPoint longer;
    {
      PhaseTimer watch(times_.line_search, objective_);
      longer.state = dofs.apply_step(state, dq, 2 * alpha);
      longer.energy = objective_.value(longer.state);
    }
    if (!std::isfinite(longer.energy) || !(longer.energy < point.energy)) break;
    compute_gradient(longer);
    point = std::move(longer);
    alpha *= 2;
  }
  return alpha;
}

NewtonResult NewtonSolver::solve(fem::State& state, const NewtonOptions& options, const IterationCallback& on_iteration) {
  Objective& objective = objective_;
  PhaseTimes& times = times_;
  const NewtonSetup& context = setup_;
  const fem::DofMap& dofs = objective.dofs();
  NewtonResult result;
  double shift_hint = 0;  // relative diagonal shift to try first (see newton_direction)
  double energy;
  {
    PhaseTimer watch(times.line_search, objective);
    energy = objective.value(state);
  }
  if (!std::isfinite(energy)) {
    result.failure = "the starting state is illegal (an element is inverted or degenerate)";
    return result;
  }
  double scale = 0;
  NodalVectors full_g;
  VectorX g;
  {
    PhaseTimer watch(times.forces_and_stiffness, objective);
    full_g = objective.full_gradient(state, &scale);
    g = dofs.reduce_gradient(state, full_g);
  }
  double residual = g.norm();
  IterationRecord record;
  record.residual = residual;
  record.force_scale = scale;
  record.energy = energy;
  record.equilibrium_residual = equilibrium_residual(dofs, state, full_g, residual, context.transient_terms);
  if (on_iteration) on_iteration(record);

  double increment = std::numeric_limits<double>::infinity();
  double previous_residual = residual;
  bool redo_exact = false;  // the last lagged step was undone: solve this iteration exactly
  for (int it = 0;; ++it) {
    const double tolerance =
        std::max(options.residual_tolerance * scale, kRoundoffResidual * context.reference_force);
    const bool small_residual = residual <= tolerance;
    const bool roundoff = residual <= kRoundoffResidual * context.reference_force;
    const bool small_increment = it == 0 || roundoff || increment <= options.increment_tolerance * context.characteristic_length;
    result.iterations = it;
    result.residual = residual;
    result.force_scale = scale;
    result.energy = energy;
    if (!std::isfinite(residual) || !std::isfinite(scale) || !std::isfinite(context.reference_force)) {
      // inf <= inf would pass the test below: an overflow is never an equilibrium.
      result.failure = fmt::format(
          "the forces are not finite (residual {}, force scale {}, reference force {}): a load, stiffness, density or "
          "penalty of the scene overflows double precision; scale the scene's units or its values down",
          residual, scale, context.reference_force);
      return result;
    }
    if ((small_residual && small_increment) || dofs.num_dofs() == 0) {
      result.converged = true;
      return result;
    }
    if (it == options.max_iterations) {
      result.failure = fmt::format("no convergence in {} Newton iterations (residual {:.3e}, tolerance {:.3e})",
                                   it, residual, tolerance);
      return result;
    }

    bool fresh = false;
    if (!redo_exact) {  // else K_ is still this state's tangent
      PhaseTimer watch(times.forces_and_stiffness, objective);
      fresh = objective.hessian(state, full_g, context.node_viscosity, K_);
    }
    Direction direction;
    {
      Stopwatch watch(times.linear_solve);
      // An inexact (lagged) solve is used while Newton makes progress; when the last iteration
      // did not halve the residual, this one solves exactly (an inexact direction can stall
      // Newton, near round-off for one; docs/solver.md, "Lagged factorizations").
      const bool stalling = redo_exact || (it > 0 && residual > 0.5 * previous_residual);
      linear_->require_relative_residual(stalling ? 0.0 : 1.0);
      prepare_linear_solver(state);
      direction = newton_direction(K_, fresh, g, *linear_,
                                   ShiftStart{.first = shift_hint, .after_unshifted_failure = last_shift_ / 10});
    }
    linear_iterations_ += direction.linear_iterations;
    factorized_ = true;  // of K_ or a shifted K_: good enough for a predictor
    // The scale for the next climb from an unshifted failure: the shift this climb reached (not
    // the decaying hints that follow it, which succeed at ever smaller shifts).
    if (shift_hint == 0 && direction.regularization > 0 && std::isfinite(direction.regularization))
      last_shift_ = direction.regularization;
    // An indefinite tangent usually stays indefinite for a few iterations: start the next
    // search a hundredfold below the shift that worked instead of from zero.
    shift_hint = std::isfinite(direction.regularization) ? direction.regularization / 100 : 0;
    const double slope = g.dot(direction.dq);

    // Line search: halve until legal and decreasing.
    double alpha = 1;
    int halvings = 0;
    bool accepted = false;
    fem::State trial;
    double trial_energy = 0;
    NodalVectors trial_full_g;
    VectorX trial_g;
    double trial_scale = 0;
    for (; halvings <= options.max_line_search_steps; ++halvings, alpha *= 0.5) {
      {
        PhaseTimer watch(times.line_search, objective);
        trial = dofs.apply_step(state, direction.dq, alpha);
        trial_energy = objective.value(trial);
      }
      if (!std::isfinite(trial_energy)) continue;
      const bool residual_rule = options.line_search == NewtonOptions::LineSearchRule::Residual;
      const double roundoff = 1e-11 * std::max({std::abs(energy), std::abs(trial_energy), 1e-300});
      const bool decreases = trial_energy <= energy + 1e-4 * alpha * slope;
      const bool flat = std::abs(trial_energy - energy) <= roundoff;
      if (!residual_rule && decreases) {
        accepted = true;
        break;
      }
      if (residual_rule || flat) {
        PhaseTimer watch(times.forces_and_stiffness, objective);
        trial_full_g = objective.full_gradient(trial, &trial_scale);
        trial_g = dofs.reduce_gradient(trial, trial_full_g);
        if (trial_g.norm() < residual) {
          accepted = true;
          break;
        }
        trial_full_g.resize(0, 3);
      }
    }
    if (!accepted) {
      result.failure = fmt::format(
          "line search failed: no legal, decreasing step after {} halvings (residual {:.3e})",
          options.max_line_search_steps, residual);
      return result;
    }
    if (options.line_search == NewtonOptions::LineSearchRule::Energy && halvings == 0 && options.max_step_growth > 1) {
      TrialPoint point{std::move(trial), trial_energy, std::move(trial_full_g), std::move(trial_g), trial_scale};
      alpha = extrapolate(state, direction.dq, slope, options.max_step_growth, point);
      trial = std::move(point.state);
      trial_energy = point.energy;
      trial_full_g = std::move(point.full_g);
      trial_g = std::move(point.g);
      trial_scale = point.scale;
    }
    if (trial_full_g.rows() == 0) {
      PhaseTimer watch(times.forces_and_stiffness, objective);
      trial_full_g = objective.full_gradient(trial, &trial_scale);
      trial_g = dofs.reduce_gradient(trial, trial_full_g);
    }
    // An inexact (lagged) direction can lower the energy into a state whose forces explode: an
    // element driven nearly flat. Undo such a step and solve this iteration exactly
    // (docs/solver.md, "Lagged factorizations").
    if (direction.lagged && !(trial_g.norm() <= options.max_lagged_residual_growth * residual)) {
      redo_exact = true;
      ++undone_lagged_steps_;
      --it;
      continue;
    }
    redo_exact = false;
    increment = largest_displacement(trial, state);
    state = std::move(trial);
    energy = trial_energy;
    full_g = std::move(trial_full_g);
    g = std::move(trial_g);
    scale = trial_scale;
    previous_residual = residual;
    residual = g.norm();

    record = IterationRecord{};
    record.iteration = it + 1;
    record.residual = residual;
    record.force_scale = scale;
    record.energy = energy;
    record.step_length = alpha;
    record.line_search_steps = halvings;
    record.linear_iterations = direction.linear_iterations;
    record.increment = increment;
    record.regularization = direction.regularization;
    record.equilibrium_residual = equilibrium_residual(dofs, state, full_g, residual, context.transient_terms);
    if (on_iteration) on_iteration(record);
  }
}

}  // namespace sinew::solver
