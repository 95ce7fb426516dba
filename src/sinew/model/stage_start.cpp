#include "sinew/model/stage_start.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "sinew/core/error.hpp"
#include "sinew/model/checkpoint.hpp"

namespace sinew::model {

void start_from_run(Model& model, const std::string& directory) {
  const std::string where = fmt::format("initial_state \"{}\"", directory);
  std::error_code ec;
  if (!std::filesystem::is_directory(directory, ec))
    throw InputError(fmt::format("{}: no such directory (it names the output directory of the run this one starts "
                                 "from)",
                                 where));
  const std::string path = directory + "/" + kCheckpointFile;
  if (!std::filesystem::exists(path, ec))
    throw InputError(fmt::format("{}: it holds no {} (a run writes one at its end; explicit integration writes none): "
                                 "run the earlier stage there first",
                                 where, kCheckpointFile));
  const Checkpoint checkpoint = read_checkpoint(path);
  const solver::StepperSnapshot& end = checkpoint.snapshot.stepper;
  const bool earlier_dynamic = end.scheme.velocity.rows() > 0;
  if (checkpoint.mesh_fingerprint == 0)
    throw InputError(fmt::format("{}: its checkpoint was written by an older sinew that did not record the meshes; "
                                 "run the earlier stage again",
                                 where));
  if (!checkpoint.finished)
    throw InputError(fmt::format("{}: that run did not finish (it stopped at {} = {:.6g}); resume it with --resume, "
                                 "then start this stage",
                                 where, earlier_dynamic ? "t" : "lambda", end.t));
  if (checkpoint.mesh_fingerprint != mesh_fingerprint(model))
    throw InputError(fmt::format("{}: that run has other meshes (nodes or tets differ from this scene's): a stage "
                                 "must use the same bodies, mesh files and meshing options as the run it starts "
                                 "from",
                                 where));
  try {
    model.dofs->set_start(end.state);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", where, e.what()));
  }
  // Velocities matter to a stage with inertia (implicit Euler or explicit central differences).
  const bool with_inertia =
      model.is_dynamic() && model.dynamics->options.integrator != solver::DynamicOptions::Integrator::Quasistatic;
  if (with_inertia && earlier_dynamic) {
    if (end.scheme.velocity.rows() != model.problem->mesh.num_nodes() || !end.scheme.velocity.allFinite())
      throw InputError(fmt::format("{}: its velocities do not fit this scene's nodes", where));
    model.start_velocity = end.scheme.velocity;
  }
  model.started_from = directory;
}

}  // namespace sinew::model
