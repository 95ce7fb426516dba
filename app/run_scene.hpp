#pragma once
/// @file run_scene.hpp
/// `sinew run`: load and check a scene, build the problem, solve, write the outputs.

#include <functional>
#include <string>

#include "sinew/scene/scene_config.hpp"
#include "sinew/solver/dynamic_solver.hpp"
#include "sinew/solver/static_solver.hpp"

namespace sinew::app {

struct RunOptions {
  std::string output_directory = "out";
  bool progress_bar = true;  ///< drawn only when stderr is a terminal
  bool log_steps = true;     ///< one log line per accepted load step
  /// Called after newton.csv got the row of every Newton iteration (step counter, then the load
  /// parameter of a static step or the target time of a dynamic one).
  std::function<void(int step, double lambda_or_time, const solver::IterationRecord& iteration)> on_iteration;
};

struct RunReport {
  bool success = false;
  std::string message;
  double wall_seconds = 0;
  double setup_seconds = 0;  ///< of wall_seconds: meshing, material depth, model set-up
  solver::StaticResult result;         ///< static analyses
  solver::DynamicResult dynamic_result;  ///< dynamic analyses
};

/// Builds and solves the scene. Input errors (InputError) propagate before anything is
/// written; a solve that fails returns success = false after writing the last converged state.
RunReport run_scene(const scene::SceneConfig& scene, const RunOptions& options);

}  // namespace sinew::app
