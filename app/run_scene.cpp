#include "run_scene.hpp"

#include <chrono>
#include <cmath>
#include <new>
#include <optional>

#include <fmt/format.h>

#include "run_output.hpp"
#include "sinew/core/error.hpp"
#include "sinew/core/log.hpp"
#include "sinew/io/output_directory.hpp"
#include "sinew/io/progress.hpp"
#include "sinew/scene/build_problem.hpp"
#include "static_model.hpp"

namespace sinew::app {

namespace {

/// Logs a line above the progress bar (clears the bar's line first; the bar redraws itself).
void log_line(const io::ProgressBar& bar, spdlog::level::level_enum level, const std::string& text) {
  if (bar.enabled()) fmt::print(stderr, "\r\033[K");
  logger().log(level, text);
}

/// "setup 5 %, forces and stiffness 41 %, collision 12 %, linear solve 30 %, line search 9 %,
/// other 3 %" of `wall_seconds`.
std::string phase_split(const solver::PhaseTimes& t, double setup_seconds, double wall_seconds) {
  const double total = std::max(wall_seconds, 1e-12);
  auto percent = [&](double seconds) { return 100 * seconds / total; };
  return fmt::format("setup (meshing, depth) {:.0f} %, forces and stiffness {:.0f} %, collision {:.0f} %, linear solve "
                     "{:.0f} %, line search {:.0f} %, other {:.0f} %",
                     percent(setup_seconds), percent(t.forces_and_stiffness), percent(t.collision),
                     percent(t.linear_solve), percent(t.line_search),
                     percent(std::max(0.0, wall_seconds - setup_seconds - t.total())));
}

RunReport run_dynamics(const scene::SceneConfig& scene, const StaticModel& model, RunOutput& output,
                       const RunOptions& options, std::chrono::steady_clock::time_point start, double setup_seconds,
                       double& reached) {
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const solver::DynamicOptions& dyn = scene.dynamics.options;
  using Integrator = solver::DynamicOptions::Integrator;
  if (dyn.integrator == Integrator::Explicit)
    logger().info("explicit central differences: critical time step {:.4g} (contact alone {:.4g}), step {:.4g} ({} x), "
                  "about {:.0f} steps",
                  model.critical_time_step, model.contact_critical_time_step, dyn.explicit_safety * model.critical_time_step, dyn.explicit_safety,
                  std::ceil(dyn.end_time / (dyn.explicit_safety * model.critical_time_step)));
  io::ProgressBar bar({.total = dyn.end_time, .label = scene.name});
  solver::DynamicCallbacks callbacks;
  callbacks.on_iteration = [&](const solver::TimeStepRecord& step, const solver::IterationRecord& it) {
    output.write_time_iteration(step, it);
    if (options.on_iteration) options.on_iteration(step.step + 1, step.time, it);
  };
  callbacks.on_step = [&](const solver::TimeStepRecord& step, const fem::State& state, const NodalVectors& velocity) {
    reached = step.time;
    output.write_time_step(step, state, velocity);
    if (options.log_steps && dyn.integrator != Integrator::Explicit)
      log_line(bar, spdlog::level::info, fmt::format("step {:5d}  t {:.6g}  h {:.3g}  newton {:2d}  |r| {:.2e}", step.step,
                                                step.time, step.step_size, step.newton_iterations, step.residual));
    bar.update(step.time, fmt::format("t {:.4g}  h {:.2g}", step.time, step.step_size));
  };
  callbacks.on_output = [&](int k, const solver::TimeStepRecord& step, const fem::State& state,
                            const NodalVectors& velocity) { output.write_output(k, step.time, state, velocity); };
  callbacks.on_cut = [&](const solver::TimeStepRecord& step, const std::string& why) {
    log_line(bar, spdlog::level::warn,
             fmt::format("time step to t = {:.6g} (h = {:.3g}) failed, halving: {}", step.time, step.step_size, why));
  };
  solver::DynamicSetup setup;
  setup.characteristic_length = model.setup.characteristic_length;
  setup.reference_force = model.setup.reference_force;
  setup.critical_time_step = model.critical_time_step;
  RunReport report;
  report.setup_seconds = setup_seconds;
  report.dynamic_result = solver::solve_dynamic(*model.objective, {model.inertia.get(), model.viscosity.get()}, dyn,
                                                scene.solver, setup, callbacks);
  bar.finish();
  report.wall_seconds = elapsed();
  report.success = report.dynamic_result.success;
  report.message = report.dynamic_result.message;
  if (!report.success) output.write_state("last_converged.vtu", report.dynamic_result.last_state);
  output.write_dynamic_summary(report.dynamic_result, report.wall_seconds, scene.name);
  const auto& r = report.dynamic_result;
  logger().info("{} at t = {:.6g} in {:.2f} s: {} steps (h {:.3g} .. {:.3g}), {} Newton iterations, {} cuts; {}",
                report.success ? "done" : "stopped", r.time, report.wall_seconds, r.steps, r.min_step, r.max_step,
                r.newton_iterations, r.cuts, phase_split(r.times, report.setup_seconds, report.wall_seconds));
  return report;
}

RunReport run_static(const scene::SceneConfig& scene, const StaticModel& model, RunOutput& output,
                     const RunOptions& options, std::chrono::steady_clock::time_point start, double setup_seconds,
                     double& reached);

}  // namespace

RunReport run_scene(const scene::SceneConfig& scene, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };

  // Everything that can fail on bad input happens before the first file is written.
  const fem::Problem problem = scene::build_problem(scene);
  const std::optional<ContactInput> contact = make_contact_input(scene, problem);
  if (contact) {
    const auto& penalty = contact->geometry.penalty;
    for (Index a = 0; a < penalty.rows(); ++a)
      for (Index b = a; b < penalty.cols(); ++b)
        if (penalty(a, b) > 0)
          logger().info("contact {} / {}: penalty {:.4g} (force/length^3)", contact->body_names[static_cast<std::size_t>(a)],
                        contact->body_names[static_cast<std::size_t>(b)], penalty(a, b));
  }
  const StaticModel model =
      make_static_model(problem, scene.solver, contact ? &*contact : nullptr, &scene.dynamics);

  const double setup_seconds = elapsed();
  logger().info("scene \"{}\": {} nodes, {} tets, {} unknowns, {} rigid bodies; meshing and set-up {:.1f} s", scene.name,
                problem.mesh.num_nodes(), problem.mesh.num_tets(), model.dofs->num_dofs(), problem.rigid_bodies.size(),
                setup_seconds);

  const io::OutputDirectoryLock lock(options.output_directory, {.overwrite = options.overwrite}, options.command);
  RunOutput output(options.output_directory, problem, model, scene.output);
  output.set_setup_seconds(setup_seconds);
  // Where the run is (lambda or time of the last accepted step), for a summary of a run that
  // stops for a failed write or for memory.
  double reached = 0;
  const char* reached_key = scene.dynamics.enabled ? "time_reached" : "lambda_reached";
  auto record_stop = [&](const char* status, const std::string& message) {
    try {
      output.write_stopped_summary(scene.name, status, message, reached_key, reached, elapsed());
    } catch (...) {  // the disk may still be full: the message on standard error remains
    }
  };
  try {
    return scene.dynamics.enabled ? run_dynamics(scene, model, output, options, start, setup_seconds, reached)
                                  : run_static(scene, model, output, options, start, setup_seconds, reached);
  } catch (const OutputError& e) {
    record_stop("output_error", e.what());
    throw;
  } catch (const OutOfMemoryError& e) {
    record_stop("out_of_memory", e.what());
    throw;
  } catch (const std::bad_alloc&) {
    const std::string message = "out of memory (an allocation failed); try a coarser mesh or a machine with more memory";
    record_stop("out_of_memory", message);
    throw OutOfMemoryError(message);
  }
}

namespace {

RunReport run_static(const scene::SceneConfig& scene, const StaticModel& model, RunOutput& output,
                     const RunOptions& options, std::chrono::steady_clock::time_point start, double setup_seconds,
                     double& reached) {
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const int increments = std::max(1, scene.solver.stepping.increments);
  io::ProgressBar bar({.total = 1.0, .label = scene.name});

  solver::StaticCallbacks callbacks;
  callbacks.on_iteration = [&](const solver::StepRecord& step, const solver::IterationRecord& it) {
    output.write_iteration(step, it);
    if (options.on_iteration) options.on_iteration(step.step, step.lambda, it);
    bar.update(step.lambda - step.step_size,
               fmt::format("increment {}/{}  newton {}  |r|={:.2e}", step.increment, increments, it.iteration,
                           it.residual));
  };
  callbacks.on_step = [&](const solver::StepRecord& step, const fem::State& state) {
    reached = step.lambda;
    output.write_step(step, state);
    if (options.log_steps)
      log_line(bar, spdlog::level::info,
               fmt::format("step {:4d}  increment {}/{}  lambda {:.5f}  newton {:2d}  |r| {:.2e} (scale {:.2e})  "
                           "energy {:.6e}{}",
                           step.step, step.increment, increments, step.lambda, step.newton_iterations, step.residual,
                           step.force_scale, step.energy, step.snap_through ? "  (snap-through: long Newton budget)" : ""));
    bar.update(step.lambda, fmt::format("increment {}/{}", step.increment, increments));
  };
  callbacks.on_cut = [&](const solver::StepRecord& step, const std::string& why) {
    log_line(bar, spdlog::level::warn,
             fmt::format("step to lambda {:.5f} (size {:.3g}) failed, halving: {}", step.lambda, step.step_size, why));
  };
  callbacks.on_increment = [&](int k, const fem::State& state) { output.write_increment(k, increments, state); };

  RunReport report;
  report.setup_seconds = setup_seconds;
  report.result = solver::solve_static(*model.objective, scene.solver, model.setup, callbacks);
  bar.finish();
  report.wall_seconds = elapsed();
  report.success = report.result.success;
  report.message = report.result.message;
  if (!report.success) output.write_state("last_converged.vtu", report.result.last_converged);
  output.write_summary(report.result, report.wall_seconds, scene.name);
  logger().info("{} in {:.2f} s: {}", report.success ? "done" : "stopped", report.wall_seconds,
                phase_split(report.result.times, report.setup_seconds, report.wall_seconds));
  return report;
}

}  // namespace

}  // namespace sinew::app
