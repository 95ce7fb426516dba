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
  LoadStepping(Objective& objective, const LoadSteppingOptions& options) : objective_(objective), options_(options) {}

  fem::State start() override {
    fem::State state = objective_.dofs().initial_state(0.0);
    objective_.set_load_parameter(0.0);
    objective_.begin_step(state);
    return state;
  }

  fem::State predict(const fem::State& current, double, double lambda_new, NewtonSolver& newton) override {
    const fem::DofMap& dofs = objective_.dofs();
    objective_.begin_step(current);
    fem::State trial;
    if (options_.predictor == Predictor::Tangent) {
      trial = tangent_prediction(current, lambda_new, newton);
    } else if (options_.predictor == Predictor::TwoPoint && has_previous_) {
      trial = dofs.extrapolate(previous_, current, (lambda_new - current.lambda) / (current.lambda - previous_.lambda),
                               lambda_new);
    } else {
      trial = current;
      dofs.sync(trial, lambda_new);
    }
    objective_.set_load_parameter(lambda_new);
    if (!objective_.is_valid(trial)) {
      trial = current;
      dofs.sync(trial, lambda_new);
    }
    return trial;
  }

  void accept(const fem::State& previous, const fem::State&, double) override {
    previous_ = previous;
    has_previous_ = true;
  }

  void reject(const fem::State& current) override { objective_.set_load_parameter(current.lambda); }

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
        "{:.3g}, min_step = {:.3g} of an increment): {}. The last converged state (lambda = {:.6g}) is kept. Try "
        "more increments, quasi-viscosity, or check that the prescribed motion is physically possible.",
        lambda, h, smallest, options_.min_step, why, lambda);
  }

  std::string solved(const StepperResult& r) const override {
    return fmt::format("solved: {} increments, {} steps, {} Newton iterations, {} step cuts{}", r.segments_completed,
                       r.steps, r.newton_iterations, r.cuts,
                       r.snap_throughs > 0
                           ? fmt::format(", {} snap-through{}", r.snap_throughs, r.snap_throughs == 1 ? "" : "s")
                           : "");
  }

 private:
  /// First-order predictor: dq = -K^-1 (dg/dlambda) dlambda, with dg/dlambda from a forward
  /// difference of the gradient under the prescribed motion and loads alone, K from the last
  /// factorization.
  fem::State tangent_prediction(const fem::State& converged, double lambda_new, NewtonSolver& newton) {
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
      objective_.set_load_parameter(lambda_new);
    }
    fem::State base = converged;
    dofs.sync(base, lambda_new);
    VectorX dq;
    if (!factorized || !newton.solve_with_last_factorization(-(gh - g0) / h * (lambda_new - lambda0), dq)) return base;
    return dofs.apply_step(base, dq, 1.0);
  }

  Objective& objective_;
  LoadSteppingOptions options_;
  fem::State previous_;
  bool has_previous_ = false;
};

}  // namespace

StepperResult solve_static(Objective& objective, const StaticSolverOptions& options, const NewtonSetup& setup,
                           const StepperCallbacks& callbacks, StepRefinement* refinement) {
  NewtonSolver newton(objective, options.linear, setup);
  LoadStepping scheme(objective, options.stepping);
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
  o.start = StepperOptions::Start::SolveEquilibrium;
  o.growth_rule = StepperOptions::Growth::AfterEasyStep;
  o.newton = options.newton;
  return run_stepper(newton, scheme, o, callbacks, refinement);
}

}  // namespace sinew::solver
