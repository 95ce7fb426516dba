#include "sinew/solver/time_stepping.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "sinew/core/error.hpp"
#include "sinew/solver/explicit_integration.hpp"
#include "sinew/solver/prescribed_turn.hpp"

namespace sinew::solver {
namespace {

void check_options(const DynamicOptions& o) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (!positive(o.end_time)) throw InputError(fmt::format("dynamics: end_time must be > 0, got {}", o.end_time));
  if (!positive(o.output_interval))
    throw InputError(fmt::format("dynamics: output_interval must be > 0, got {}", o.output_interval));
  if (!(o.explicit_safety > 0 && o.explicit_safety <= 1))
    throw InputError(fmt::format("dynamics: explicit_safety must be in (0, 1], got {}", o.explicit_safety));
}

class ImplicitTimeStepping final : public StepScheme {
 public:
  ImplicitTimeStepping(Objective& objective, const DynamicTerms& terms, bool with_inertia, double end_time,
                       NodalVectors initial_velocity)
      : objective_(objective),
        terms_(terms),
        with_inertia_(with_inertia),
        end_time_(end_time),
        velocity_(std::move(initial_velocity)) {}

  fem::State start() override {
    fem::State state = objective_.dofs().initial_state(0.0);
    if (velocity_.rows() == 0) velocity_ = NodalVectors::Zero(state.x.rows(), 3);
    return state;
  }

  fem::State predict(const fem::State& current, double t, double t_new, NewtonSolver&) override {
    const double h = t_new - t;
    // From the converged state: terms that lag quantities per step (friction) take it as the
    // step's start, and the step's size.
    objective_.set_time_step(h);
    objective_.begin_step(current);
    fem::State trial = current;
    const double lambda = std::min(1.0, t_new / end_time_);
    objective_.dofs().sync(trial, lambda);
    objective_.set_load_parameter(lambda);
    if (with_inertia_) terms_.inertia->set_center_and_scale(current.x + h * velocity_, 1.0 / (h * h));
    if (terms_.viscosity) terms_.viscosity->set_center_and_scale(current.x, 1.0 / h);
    return trial;
  }

  void accept(const fem::State& previous, const fem::State& current, double h) override {
    velocity_ = (current.x - previous.x) / h;
  }

  void reject(const fem::State& current) override { objective_.set_load_parameter(current.lambda); }

  SchemeMemory memory(const fem::State&, NewtonSolver&) override {
    SchemeMemory memory;
    memory.velocity = velocity_;
    return memory;
  }

  void restore(const fem::State& current, const SchemeMemory& memory) override {
    velocity_ = memory.velocity;
    objective_.set_load_parameter(current.lambda);
    objective_.begin_step(current);
  }

  const NodalVectors& velocity() const override { return velocity_; }

  double bound_step(double t, double h, double smallest) const override {
    const double T = end_time_;
    return T * step_within_turn_bound(objective_.dofs(), t / T, h / T, smallest / T);
  }

  std::string start_failed(const std::string& why) const override {
    return fmt::format("the start state cannot be used: {}", why);
  }

  std::string turn_too_fast(double t, double smallest) const override {
    return fmt::format(
        "a prescribed motion turns by more than {:.0f} degrees within the smallest allowed time step from "
        "t = {:.6g} (min_time_step {:.3g}): slow the rotation down (a longer end_time) or allow smaller steps",
        kMaxPrescribedTurnPerStep * 180 / std::numbers::pi, t, smallest);
  }

  std::string step_too_small(double t, double h, double smallest, const std::string& why) const override {
    return fmt::format(
        "the time step from t = {:.6g} could not be solved even with h = {:.3g} (min_time_step {:.3g}): {}. "
        "The last converged state (t = {:.6g}) is kept. Try a smaller time_step or more damping.",
        t, h, smallest, why, t);
  }

  std::string solved(const StepperResult& r) const override {
    return fmt::format("solved: t = {:.6g} in {} time steps, {} Newton iterations, {} cuts", r.t, r.steps,
                       r.newton_iterations, r.cuts);
  }

 private:
  Objective& objective_;
  DynamicTerms terms_;
  bool with_inertia_;
  double end_time_;
  NodalVectors velocity_;
};

}  // namespace

StepperResult solve_dynamic(Objective& objective, const DynamicTerms& terms, const DynamicOptions& options,
                            const StaticSolverOptions& newton_options, const NewtonSetup& setup,
                            const DynamicSetup& dynamic_setup, const StepperCallbacks& callbacks,
                            StepRefinement* refinement) {
  check_options(options);
  if (options.integrator == DynamicOptions::Integrator::Explicit)
    return solve_explicit(objective, terms, options, dynamic_setup, callbacks);
  const bool with_inertia = options.integrator == DynamicOptions::Integrator::ImplicitEuler;
  if (with_inertia && !terms.inertia) throw InputError("implicit Euler needs an inertia term (the mass matrix)");

  NewtonSetup newton_setup = setup;
  if (with_inertia) newton_setup.transient_terms.push_back(terms.inertia);
  if (terms.viscosity) newton_setup.transient_terms.push_back(terms.viscosity);
  NewtonSolver newton(objective, newton_options.linear, std::move(newton_setup));
  ImplicitTimeStepping scheme(objective, terms, with_inertia, options.end_time, dynamic_setup.initial_velocity);

  const double max_step = options.max_time_step > 0 ? options.max_time_step : options.output_interval;
  const double first_step = std::min(max_step, options.time_step > 0 ? options.time_step : options.output_interval / 10);
  StepperOptions o;
  o.end = options.end_time;
  o.segment_length = options.output_interval;
  o.first_step = first_step;
  o.max_step = max_step;
  o.min_step = options.min_time_step > 0 ? options.min_time_step : 1e-6 * first_step;
  o.growth = options.growth;
  o.easy_iterations = options.easy_iterations;
  o.snap_to_segment_end = 0;
  o.snap_through_after_cuts = 0;
  o.start = StepperOptions::Start::GivenState;
  o.growth_rule = StepperOptions::Growth::AfterEasyFullStep;
  o.newton = newton_options.newton;
  o.resume = dynamic_setup.resume;
  return run_stepper(newton, scheme, o, callbacks, refinement);
}

}  // namespace sinew::solver
