#pragma once
/// @file run_scene.hpp
/// `sinew run`: load and check a scene, build the problem, solve, write the outputs.

#include <functional>
#include <string>

#include "sinew/scene/scene_config.hpp"
#include "sinew/model/checkpoint.hpp"
#include "sinew/model/model.hpp"
#include "sinew/solver/stepper.hpp"

namespace sinew::app {

struct RunOptions {
  std::string output_directory = "out";
  bool progress_bar = true;  ///< drawn only when stderr is a terminal
  bool log_steps = true;     ///< one log line per accepted load step
  bool overwrite = false;    ///< empty an earlier sinew run's output directory first
  std::string command;       ///< recorded in the output directory's lock file (which run holds it)
  /// Continue the run in output_directory from its checkpoint (docs/checkpoints.md).
  bool resume = false;
  /// What identifies the scene besides its meshes (the scene file's text and the command-line
  /// overrides): hashed into the checkpoint, which a resume of another scene is refused by.
  std::string scene_identity;
  /// The command that resumes this run, for the message of an interrupted run (default: the
  /// command with " --resume").
  std::string resume_command;
  /// Called after newton.csv got the row of every Newton iteration (step counter, then the load
  /// parameter of a static step or the target time of a dynamic one).
  std::function<void(int step, double lambda_or_time, const solver::IterationRecord& iteration)> on_iteration;
};

struct RunReport {
  bool success = false;
  std::string message;
  double wall_seconds = 0;
  double setup_seconds = 0;  ///< of wall_seconds: meshing, material depth, model set-up
  solver::StepperResult result;
};

/// Builds and solves the scene. Input errors (InputError) propagate before anything is
/// written; then the output directory is locked and emptied (io::OutputDirectoryLock), or, with
/// `resume`, kept and the run continued from its checkpoint. A checkpoint is written after
/// accepted steps (output.checkpoint_every). A solve that fails returns success = false after
/// writing the last converged state. A failed write (OutputError) or exhausted memory
/// (OutOfMemoryError, from std::bad_alloc too) propagates after summary.json has recorded where
/// the run stopped, if it could still be written; SIGINT or SIGTERM ends the run with
/// RunInterrupted (interrupt.hpp) after the checkpoint and last_converged.vtu are written.
RunReport run_scene(const scene::SceneConfig& scene, const RunOptions& options);

/// The same with a model built already (by model::build_model; `setup_seconds` it took). The
/// model's state is changed by the run (the contact pairs, the inertia centre).
/// With `resume` (or options.resume, which reads the output directory's checkpoint), the run
/// goes on from that checkpoint; InputError when it is of another scene.
RunReport run_model(model::Model& model, const scene::OutputConfig& output, const RunOptions& options,
                    double setup_seconds = 0, const model::Checkpoint* resume = nullptr);

}  // namespace sinew::app
