#include "run_scene.hpp"

#include <chrono>
#include <filesystem>
#include <optional>
#include <cmath>
#include <new>

#include <fmt/format.h>

#include "interrupt.hpp"
#include "parallel_run.hpp"
#include "run_checkpoints.hpp"
#include "run_output.hpp"
#include "sinew/core/error.hpp"
#include "sinew/core/log.hpp"
#include "sinew/core/stopwatch.hpp"
#include "sinew/io/output_directory.hpp"
#include "sinew/io/progress.hpp"
#include "sinew/model/solve_model.hpp"
#include "sinew/parallel/ranks.hpp"
#include "sinew/parallel/root_for_all.hpp"

namespace sinew::app {

namespace {

/// The checkpoint in `directory`, read before any work; InputError when there is none.
model::Checkpoint read_run_checkpoint(const std::string& directory) {
  io::check_output_directory(directory, {.resume = true});
  const std::string path = directory + "/" + model::kCheckpointFile;
  if (!std::filesystem::exists(path))
    throw InputError(fmt::format("there is no checkpoint in \"{}\" ({} is missing: the run stopped before its first "
                                 "step, wrote none, or used explicit integration): run the scene again with --overwrite instead of --resume",
                                 directory, model::kCheckpointFile));
  return model::read_checkpoint(path);
}

using Integrator = solver::DynamicOptions::Integrator;

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

/// The callbacks that write the outputs and the log of a run, static or dynamic.
/// Throws RunInterrupted when SIGINT or SIGTERM came (the caller writes the checkpoint).
void stop_if_interrupted() {
  // On several ranks every rank stops at the same point (the signal may reach them at different
  // moments): the largest signal number pending on any rank.
  const int local = InterruptGuard::pending();
  const int signal = parallel::size() > 1 ? static_cast<int>(parallel::max(local)) : local;
  if (signal) throw RunInterrupted(InterruptGuard::name(signal));
}

solver::StepperCallbacks output_callbacks(const model::Model& model, RunOutput& output, io::ProgressBar& bar,
                                          const RunOptions& options, double& reached, RunCheckpoints& checkpoints) {
  const bool dynamic = model.is_dynamic();
  const bool explicit_steps = dynamic && model.dynamics->options.integrator == Integrator::Explicit;
  const int increments = std::max(1, model.solver.stepping.increments);
  solver::StepperCallbacks callbacks;
  callbacks.on_iteration = [&output, &options, &bar, dynamic, increments](const solver::StepRecord& step,
                                                                         const solver::IterationRecord& it) {
    output.write_iteration(step, it);
    if (options.on_iteration) options.on_iteration(step.step, step.t, it);
    stop_if_interrupted();
    if (!dynamic)
      bar.update(step.t - step.step_size, fmt::format("increment {}/{}  newton {}  |r|={:.2e}", step.segment,
                                                      increments, it.iteration, it.residual));
  };
  callbacks.on_step = [&output, &options, &bar, &reached, dynamic, explicit_steps, increments](
                          const solver::StepRecord& step, const fem::State& state, const NodalVectors& velocity) {
    reached = step.t;
    if (dynamic) {
      output.write_time_step(step, state, velocity);
      if (options.log_steps && !explicit_steps)
        log_line(bar, spdlog::level::info, fmt::format("step {:5d}  t {:.6g}  h {:.3g}  newton {:2d}  |r| {:.2e}",
                                                      step.step, step.t, step.step_size, step.newton_iterations,
                                                      step.residual));
      bar.update(step.t, fmt::format("t {:.4g}  h {:.2g}", step.t, step.step_size));
      return;
    }
    output.write_step(step, state);
    if (options.log_steps)
      log_line(bar, spdlog::level::info,
               fmt::format("step {:4d}  increment {}/{}  lambda {:.5f}  newton {:2d}  |r| {:.2e} (scale {:.2e})  "
                           "energy {:.6e}{}{}",
                           step.step, step.segment, increments, step.t, step.newton_iterations, step.residual,
                           step.force_scale, step.energy, step.snap_through ? "  (snap-through: long Newton budget)" : "",
                           step.dissipated > 0 ? fmt::format("  (stabilized: {:.3e} dissipated)", step.dissipated)
                                               : ""));
    bar.update(step.t, fmt::format("increment {}/{}", step.segment, increments));
  };
  callbacks.on_segment = [&output, dynamic, increments](int k, const solver::StepRecord& step, const fem::State& state,
                                                        const NodalVectors& velocity) {
    if (dynamic)
      output.write_output(k, step.t, state, velocity);
    else
      output.write_increment(k, increments, state);
  };
  callbacks.on_accepted = [&checkpoints](const solver::StepperSnapshot& snapshot) {
    check_ranks_agree(snapshot.state, snapshot.t, snapshot.counts.steps);
    checkpoints.on_accepted(snapshot);
    stop_if_interrupted();
  };
  callbacks.on_cut = [&bar, dynamic](const solver::StepRecord& step, const std::string& why) {
    log_line(bar, spdlog::level::warn,
             dynamic ? fmt::format("time step to t = {:.6g} (h = {:.3g}) failed, halving: {}", step.t, step.step_size, why)
                     : fmt::format("step to lambda {:.5f} (size {:.3g}) failed, halving: {}", step.t, step.step_size,
                                   why));
  };
  callbacks.on_stabilize = [&bar](const solver::StepRecord& step, const std::string& why) {
    log_line(bar, spdlog::level::warn,
             fmt::format("step to lambda {:.6g} failed at the smallest allowed size ({:.3g}): {}. Going on with "
                         "viscous stabilization (solver.stabilization) for the rest of the run; the energy it "
                         "dissipates is reported in summary.json",
                         step.t, step.step_size, why));
  };
  return callbacks;
}

RunReport solve_and_write(model::Model& model, RunOutput& output, const RunOptions& options,
                          std::chrono::steady_clock::time_point start, double setup_seconds, double& reached,
                          RunCheckpoints& checkpoints, const model::Checkpoint* resume) {
  const bool dynamic = model.is_dynamic();
  if (dynamic && model.dynamics->options.integrator == Integrator::Explicit) {
    const model::Dynamics& d = *model.dynamics;
    logger().info("explicit central differences: critical time step {:.4g} (contact alone {:.4g}), step {:.4g} ({} x), "
                  "about {:.0f} steps",
                  d.critical_time_step, d.contact_critical_time_step, d.options.explicit_safety * d.critical_time_step,
                  d.options.explicit_safety,
                  std::ceil(d.options.end_time / (d.options.explicit_safety * d.critical_time_step)));
  }
  io::ProgressBar bar({.total = dynamic ? model.dynamics->options.end_time : 1.0, .label = model.name});
  RunReport report;
  report.setup_seconds = setup_seconds;
  report.result = model::solve_model(model, output_callbacks(model, output, bar, options, reached, checkpoints),
                                     resume ? &resume->snapshot : nullptr);
  bar.finish();
  report.wall_seconds = seconds_since(start);
  report.success = report.result.success;
  report.message = report.result.message;
  if (!report.success) output.write_state("last_converged.vtu", report.result.last_state);
  output.write_summary(report.result, report.wall_seconds, model.name);
  checkpoints.write_latest(report.success);  // after the tables are on disk: it counts their rows
  const auto& r = report.result;
  const std::string split = phase_split(r.times, report.setup_seconds, report.wall_seconds);
  if (dynamic)
    logger().info("{} at t = {:.6g} in {:.2f} s: {} steps (h {:.3g} .. {:.3g}), {} Newton iterations, {} cuts; {}",
                  report.success ? "done" : "stopped", r.t, report.wall_seconds, r.steps, r.min_step, r.max_step,
                  r.newton_iterations, r.cuts, split);
  else
    logger().info("{} in {:.2f} s: {}", report.success ? "done" : "stopped", report.wall_seconds, split);
  return report;
}

}  // namespace

RunReport run_scene(const scene::SceneConfig& scene, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  // Everything that can fail on bad input happens before the first file is written; a
  // checkpoint to resume from is read before the meshing.
  std::optional<model::Checkpoint> checkpoint;
  if (options.resume) checkpoint = read_run_checkpoint(options.output_directory);
  model::Model model = model::build_model(scene);
  const double setup_seconds = seconds_since(start);
  return run_model(model, scene.output, options, setup_seconds, checkpoint ? &*checkpoint : nullptr);
}

RunReport run_model(model::Model& model, const scene::OutputConfig& output_config, const RunOptions& options,
                    double setup_seconds, const model::Checkpoint* resume_from) {
  std::optional<model::Checkpoint> read;
  if (options.resume && !resume_from) resume_from = &read.emplace(read_run_checkpoint(options.output_directory));
  const std::uint64_t fingerprint = model::model_fingerprint(model, options.scene_identity);
  if (resume_from) {
    const std::string source = fmt::format("the checkpoint in \"{}\"", options.output_directory);
    if (resume_from->fingerprint != fingerprint)
      throw InputError(fmt::format(
          "{} belongs to another scene (the scene file, its meshes or the command-line overrides changed since it "
          "was written): resume with the same scene and options, or start anew with --overwrite or another -o",
          source));
    model::check_snapshot_fits(model, resume_from->snapshot, source);
  }
  const auto start = std::chrono::steady_clock::now() -
                     std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                         std::chrono::duration<double>(setup_seconds));
  const fem::Problem& problem = *model.problem;
  if (model.contact) {
    const auto& penalty = model.contact->geometry().penalty;
    const auto& names = model.contact_body_names();
    for (Index a = 0; a < penalty.rows(); ++a)
      for (Index b = a; b < penalty.cols(); ++b)
        if (penalty(a, b) > 0)
          logger().info("contact {} / {}: penalty {:.4g} (force/length^3)", names[static_cast<std::size_t>(a)],
                        names[static_cast<std::size_t>(b)], penalty(a, b));
  }
  logger().info("scene \"{}\": {} nodes, {} tets, {} unknowns, {} rigid bodies; meshing and set-up {:.1f} s", model.name,
                problem.mesh.num_nodes(), problem.mesh.num_tets(), model.dofs->num_dofs(), problem.rigid_bodies.size(),
                setup_seconds);

  if (!model.started_from.empty()) {
    // Writing a stage over the run it starts from would destroy that run (and with it the start
    // that a --resume of the stage checks).
    std::error_code start_error, output_error;
    const auto start_run = std::filesystem::weakly_canonical(model.started_from, start_error);
    const auto this_run = std::filesystem::weakly_canonical(options.output_directory, output_error);
    if (!start_error && !output_error && start_run == this_run)
      throw InputError(fmt::format("the output directory \"{}\" is the run this scene starts from (initial_state): "
                                   "write this stage into another directory",
                                   options.output_directory));
  }
  if (!model.started_from.empty())
    logger().info("starting from the end of the run in {}{}", model.started_from,
                  model.start_velocity.rows() > 0 ? " (its positions and velocities)" : " (its positions)");
  std::optional<io::OutputDirectoryLock> lock;  // rank 0's; the other ranks write nothing
  parallel::on_root_for_all([&] {
    lock.emplace(options.output_directory, io::OutputDirectoryOptions{.overwrite = options.overwrite,
                                                                      .resume = resume_from != nullptr},
                 options.command);
  });
  RunOutput output(options.output_directory, model, output_config);
  output.set_setup_seconds(setup_seconds);
  if (resume_from) {
    output.resume(*resume_from);
    const solver::StepperSnapshot& s = resume_from->snapshot.stepper;
    logger().info("resuming after step {} ({} = {:.6g}) from {}/{}", s.counts.steps,
                  model.is_dynamic() ? "t" : "lambda", s.t, options.output_directory, model::kCheckpointFile);
  }
  RunCheckpoints checkpoints(model, output, output_config.checkpoint_every, fingerprint);
  const InterruptGuard interrupt_guard;
  // Where the run is (lambda or time of the last accepted step), for a summary of a run that
  // stops for a failed write or for memory.
  double reached = 0;
  auto record_stop = [&](const char* status, const std::string& message) {
    try {
      const model::RunSnapshot* last = checkpoints.latest();
      output.write_stopped_summary(model.name, status, message, reached, seconds_since(start),
                                   last ? &last->stepper : nullptr);
    } catch (...) {  // the disk may still be full: the message on standard error remains
    }
  };
  try {
    return solve_and_write(model, output, options, start, setup_seconds, reached, checkpoints, resume_from);
  } catch (const RunInterrupted& e) {
    std::string message;
    const model::RunSnapshot* last = checkpoints.latest();
    if (last) {
      const std::string resume_command =
          !options.resume_command.empty() ? options.resume_command : options.command + " --resume";
      message = fmt::format("interrupted by {} at {} = {:.6g} (step {}): the last converged state is checkpointed in "
                            "{}; go on with: {}",
                            e.what(), model.is_dynamic() ? "t" : "lambda", last->stepper.t,
                            last->stepper.counts.steps, checkpoints.path(), resume_command);
    } else {
      message = fmt::format("interrupted by {} before the first step was accepted: there is nothing to resume, run "
                            "the scene again",
                            e.what());
    }
    record_stop("interrupted", message);  // flushes the tables the checkpoint counts rows of
    if (last) {
      checkpoints.write_latest();
      output.write_state("last_converged.vtu", last->stepper.state);
    }
    throw RunInterrupted(message);
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

}  // namespace sinew::app
