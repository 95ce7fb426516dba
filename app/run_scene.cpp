#include "run_scene.hpp"

#include <chrono>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "run_output.hpp"
#include "sinew/core/log.hpp"
#include "sinew/io/progress.hpp"
#include "sinew/scene/build_contact.hpp"
#include "sinew/scene/build_problem.hpp"
#include "static_model.hpp"

namespace sinew::app {

RunReport run_scene(const scene::SceneConfig& scene, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };

  // Everything that can fail on bad input happens before the first file is written.
  const fem::Problem problem = scene::build_problem(scene);
  std::optional<ContactInput> contact;
  if (scene.contact.enabled) {
    scene::ContactSetup setup = scene::build_contact(scene, problem);
    const auto& penalty = setup.geometry.penalty;
    for (Index a = 0; a < penalty.rows(); ++a)
      for (Index b = a; b < penalty.cols(); ++b)
        if (penalty(a, b) > 0)
          logger().info("contact {} / {}: penalty {:.4g} (force/length^3)", setup.body_names[static_cast<std::size_t>(a)],
                        setup.body_names[static_cast<std::size_t>(b)], penalty(a, b));
    contact = ContactInput{std::move(setup.geometry), setup.options, std::move(setup.body_names)};
  }
  const StaticModel model = make_static_model(problem, scene.solver, contact ? &*contact : nullptr);
  logger().info("scene \"{}\": {} nodes, {} tets, {} unknowns, {} rigid bodies", scene.name, problem.mesh.num_nodes(),
                problem.mesh.num_tets(), model.dofs->num_dofs(), problem.rigid_bodies.size());

  RunOutput output(options.output_directory, problem, model, scene.output);
  const int increments = std::max(1, scene.solver.stepping.increments);
  io::ProgressBar bar({.total = 1.0, .label = scene.name});
  auto log_line = [&](auto level, const std::string& text) {
    if (bar.enabled()) fmt::print(stderr, "\r\033[K");
    logger().log(level, text);
  };

  solver::StaticCallbacks callbacks;
  callbacks.on_iteration = [&](const solver::StepRecord& step, const solver::IterationRecord& it) {
    output.write_iteration(step, it);
    bar.update(step.lambda - step.step_size,
               fmt::format("increment {}/{}  newton {}  |r|={:.2e}", step.increment, increments, it.iteration,
                           it.residual));
  };
  callbacks.on_step = [&](const solver::StepRecord& step, const fem::State& state) {
    output.write_step(step, state);
    if (options.log_steps)
      log_line(spdlog::level::info,
               fmt::format("step {:4d}  increment {}/{}  lambda {:.5f}  newton {:2d}  |r| {:.2e} (scale {:.2e})  "
                           "energy {:.6e}",
                           step.step, step.increment, increments, step.lambda, step.newton_iterations, step.residual,
                           step.force_scale, step.energy));
    bar.update(step.lambda, fmt::format("increment {}/{}", step.increment, increments));
  };
  callbacks.on_cut = [&](const solver::StepRecord& step, const std::string& why) {
    log_line(spdlog::level::warn,
             fmt::format("step to lambda {:.5f} (size {:.3g}) failed, halving: {}", step.lambda, step.step_size, why));
  };
  callbacks.on_increment = [&](int k, const fem::State& state) { output.write_increment(k, increments, state); };

  RunReport report;
  report.result = solver::solve_static(*model.objective, scene.solver, model.setup, callbacks);
  bar.finish();
  report.wall_seconds = elapsed();
  report.success = report.result.success;
  report.message = report.result.message;
  if (!report.success) output.write_state("last_converged.vtu", report.result.last_converged);
  output.write_summary(report.result, report.wall_seconds, scene.name);
  const auto& t = report.result.times;
  const double total = std::max(report.wall_seconds, 1e-12);
  logger().info("{} in {:.2f} s: forces and stiffness {:.0f} %, linear solve {:.0f} %, line search {:.0f} %, other {:.0f} %",
                report.success ? "done" : "stopped", report.wall_seconds, 100 * t.forces_and_stiffness / total,
                100 * t.linear_solve / total, 100 * t.line_search / total,
                100 * std::max(0.0, total - t.total()) / total);
  return report;
}

}  // namespace sinew::app
