#include "sinew/solver/load_stepping.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "sinew/solver/prescribed_turn.hpp"

namespace sinew::solver {
namespace {

using Predictor = LoadSteppingOptions::Predictor;

class LoadStepping final : public StepScheme {
 public:
  LoadStepping(Objective& objective, const LoadSteppingOptions& options, fem::QuadraticEnergy* stabilization)
      : objective_(objective), options_(options), stabilization_(stabilization) {}

  fem::State start() override {
    fem::State state = objective_.dofs().initial_state(0.0);
    objective_.set_load_parameter(0.0);
    objective_.begin_step(state);
    return state;
  }

  fem::State predict(const fem::State& current, double, double lambda_new, NewtonSolver& newton) override {
    const fem::DofMap& dofs = objective_.dofs();
    // The direction memory() computed at this state (after its begin_step there), once; a
    // retry after a cut computes its own with the failed attempt's factorization, as below.
    const bool cached_tangent = options_.predictor == Predictor::Tangent && tangent_.size() > 0;
    if (!cached_tangent) objective_.begin_step(current);
    fem::State trial;
    if (cached_tangent) {
      trial = dofs.apply_step(synced(current, lambda_new), (lambda_new - current.lambda) * tangent_, 1.0);
      tangent_.resize(0);
    } else if (options_.predictor == Predictor::Tangent) {
      trial = tangent_prediction(current, lambda_new, newton);
    } else if (options_.predictor == Predictor::TwoPoint && has_previous_) {
      trial = dofs.extrapolate(previous_, current, (lambda_new - current.lambda) / (current.lambda - previous_.lambda),
                               lambda_new);
    } else {
      trial = current;
      dofs.sync(trial, lambda_new);
    }
    objective_.set_load_parameter(lambda_new);
    if (stabilized_) stabilization_->set_center_and_scale(current.x, 1.0 / (lambda_new - current.lambda));
    if (!objective_.is_valid(trial)) {
      trial = current;
      dofs.sync(trial, lambda_new);
    }
    return trial;
  }

  void accept(const fem::State& previous, const fem::State& current, double) override {
    // At the converged state the term is (1 / (2 h)) sum D_a |dx_a|²: half the work of its forces.
    dissipated_ = stabilized_ ? 2 * stabilization_->value(current.x) : 0.0;
    previous_ = previous;
    has_previous_ = true;
    tangent_.resize(0);
  }

  SchemeMemory memory(const fem::State& current, NewtonSolver& newton) override {
    SchemeMemory memory;
    memory.stabilized = stabilized_;
    if (has_previous_) memory.previous = previous_;
    if (options_.predictor == Predictor::Tangent) {
      objective_.begin_step(current);
      tangent_ = tangent_direction(current, newton);
      objective_.set_load_parameter(current.lambda);
      memory.tangent = tangent_;
    }
    return memory;
  }

  void restore(const fem::State& current, const SchemeMemory& memory) override {
    has_previous_ = memory.previous.x.rows() > 0;
    previous_ = memory.previous;
    tangent_ = memory.tangent;
    stabilized_ = memory.stabilized && stabilization_;
    objective_.set_load_parameter(current.lambda);
    objective_.begin_step(current);
  }

  void reject(const fem::State& current) override { objective_.set_load_parameter(current.lambda); }

  bool start_stabilizing() override {
    if (!stabilization_ || stabilized_) return false;
    stabilized_ = true;
    return true;
  }

  double last_dissipation() const override { return dissipated_; }

  double bound_step(double lambda, double h, double smallest) const override {
    return step_within_turn_bound(objective_.dofs(), lambda, h, smallest);
  }

  std::string start_failed(const std::string& why) const override {
    return fmt::format("the initial state (lambda = 0) has no equilibrium the solver could find: {}", why);
  }

  std::string turn_too_fast(double lambda, double smallest) const override {
    return fmt::format(
        "a prescribed motion turns by more than {:.0f} degrees within the smallest allowed load step from "
        "lambda = {:.6g} ({:.3g}, min_step = {:.3g} of an increment): give the rotation fewer degrees per "
        "increment (more increments) or a larger min_step",
        kMaxPrescribedTurnPerStep * 180 / std::numbers::pi, lambda, smallest, options_.min_step);
  }

  std::string step_too_small(double lambda, double h, double smallest, const std::string& why) const override {
    return fmt::format(
        "load step from lambda = {:.6g} could not be solved even with a step of {:.3g} (the smallest allowed is "
        "{:.3g}, min_step = {:.3g} of an increment){}: {}. The last converged state (lambda = {:.6g}) is kept. Try "
        "more increments, {}or check that the prescribed motion is physically possible.",
        lambda, h, smallest, options_.min_step, stabilized_ ? " with the viscous stabilization on" : "", why, lambda,
        stabilized_ ? "a larger solver.stabilization, "
                    : (stabilization_ ? "" : "solver.stabilization > 0 (viscous damping where the steps get stuck), "));
  }

  std::string solved(const StepperResult& r) const override {
    return fmt::format("solved: {} increments, {} steps, {} Newton iterations, {} step cuts{}", r.segments_completed,
                       r.steps, r.newton_iterations, r.cuts,
                       r.snap_throughs > 0
                           ? fmt::format(", {} snap-through{}", r.snap_throughs, r.snap_throughs == 1 ? "" : "s")
                           : "");
  }

 private:
  /// `state` synced to the prescribed motion at `lambda`.
  fem::State synced(const fem::State& state, double lambda) const {
    fem::State out = state;
    objective_.dofs().sync(out, lambda);
    return out;
  }

  /// First-order predictor: dq/dlambda = -K^-1 (dg/dlambda), with dg/dlambda from a forward
  /// difference of the gradient under the prescribed motion and loads alone, K from the last
  /// factorization (made at `converged` when there is none). Empty when the solve fails. Leaves
  /// the objective's load parameter at converged.lambda + a small nudge.
  VectorX tangent_direction(const fem::State& converged, NewtonSolver& newton) {
    const fem::DofMap& dofs = objective_.dofs();
    const double lambda0 = converged.lambda;
    const double h = 1e-6 * std::max(1.0, std::abs(lambda0));
    VectorX g0, gh;
    NodalVectors g0_full;
    {
      PhaseTimer watch(newton.times().forces_and_stiffness, objective_);
      objective_.set_load_parameter(lambda0);
      g0_full = objective_.full_gradient(converged);
      g0 = dofs.reduce_gradient(converged, g0_full);
    }
    const bool factorized = newton.ensure_factorization(converged, g0_full);
    {
      PhaseTimer watch(newton.times().forces_and_stiffness, objective_);
      fem::State nudged = converged;
      dofs.sync(nudged, lambda0 + h);
      objective_.set_load_parameter(lambda0 + h);
      gh = dofs.reduce_gradient(nudged, objective_.full_gradient(nudged));
    }
    VectorX tangent;
    if (!factorized || !newton.solve_with_last_factorization(-(gh - g0) / h, tangent)) return {};
    return tangent;
  }

  /// The tangent predictor's state at lambda_new from `converged`; the objective is left at lambda_new.
  fem::State tangent_prediction(const fem::State& converged, double lambda_new, NewtonSolver& newton) {
    const VectorX tangent = tangent_direction(converged, newton);
    objective_.set_load_parameter(lambda_new);
    fem::State base = synced(converged, lambda_new);
    if (tangent.size() == 0) return base;
    return objective_.dofs().apply_step(base, (lambda_new - converged.lambda) * tangent, 1.0);
  }

  Objective& objective_;
  LoadSteppingOptions options_;
  fem::QuadraticEnergy* stabilization_;  ///< null: none
  bool stabilized_ = false;
  double dissipated_ = 0;  ///< by the stabilization in the last accepted step
  fem::State previous_;
  bool has_previous_ = false;
  VectorX tangent_;  ///< dq/dlambda at the last accepted state, from memory(); empty once used
};

}  // namespace

StepperResult solve_static(Objective& objective, const StaticSolverOptions& options, const NewtonSetup& setup,
                           const StepperCallbacks& callbacks, StepRefinement* refinement,
                           const StepperSnapshot* resume, fem::QuadraticEnergy* stabilization) {
  NewtonSetup newton_setup = setup;
  if (stabilization) newton_setup.transient_terms.push_back(stabilization);
  NewtonSolver newton(objective, options.linear, std::move(newton_setup));
  LoadStepping scheme(objective, options.stepping, stabilization);
  const LoadSteppingOptions& stepping = options.stepping;
  const int increments = std::max(1, stepping.increments);
  const double increment = 1.0 / increments;
  StepperOptions o;
  o.end = 1;
  o.segment_length = increment;
  o.first_step = increment;
  o.max_step = increment;
  o.min_step = stepping.min_step * increment;
  o.growth = stepping.growth;
  o.easy_iterations = stepping.easy_iterations;
  o.snap_to_segment_end = 1e-6;
  o.snap_through_after_cuts = stepping.snap_through_after_cuts;
  o.snap_through_iterations = stepping.snap_through_iterations;
  // A sixteenth of an increment: the Visible Human knee, stuck at 139.5 degrees (increments of
  // 3 degrees), went on in stabilized steps of that size, 10-14 Newton iterations each
  // (docs/solver.md, "Stabilization where the steps get stuck").
  o.stabilized_step = increment / 16;
  o.start = StepperOptions::Start::SolveEquilibrium;
  o.growth_rule = StepperOptions::Growth::AfterEasyStep;
  o.newton = options.newton;
  o.resume = resume;
  return run_stepper(newton, scheme, o, callbacks, refinement);
}

}  // namespace sinew::solver
