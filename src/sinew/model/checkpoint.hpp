#pragma once
/// @file checkpoint.hpp
/// Checkpoints of a run (docs/checkpoints.md): everything a run of a Model needs to go on after
/// an accepted step exactly as it would have, written to one file atomically, and read back
/// with a clear error when the file is not a checkpoint, is damaged, or belongs to another
/// scene.

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sinew/model/model.hpp"
#include "sinew/solver/stepper.hpp"

namespace sinew::model {

/// The run's state after an accepted step: the stepper's, and what the contact term changed
/// during the run (penalties grown by the adaptive penalty, augmented Lagrangian pressures).
struct RunSnapshot {
  solver::StepperSnapshot stepper;
  MatrixX contact_penalty;   ///< bodies x bodies (force / length³); 0 x 0 without contact
  VectorX contact_pressure;  ///< #V augmented Lagrangian pressures (force / length²), or empty
};

/// `stepper` with the contact state of `model` now (after the step was accepted).
RunSnapshot take_snapshot(const Model& model, const solver::StepperSnapshot& stepper);

/// A checkpoint file: a snapshot, the identity of the scene it belongs to, and what the writer
/// of the outputs needs to go on (its own counters and the series of written VTU files).
struct Checkpoint {
  std::uint64_t fingerprint = 0;  ///< model_fingerprint of the run's model
  /// mesh_fingerprint of the run's meshes: a later stage starting from this run checks that its
  /// meshes are the same (0 in checkpoints of sinew before sequential stages).
  std::uint64_t mesh_fingerprint = 0;
  /// The run reached its end (the last checkpoint of a finished run); a later stage starts only
  /// from a finished run.
  bool finished = false;
  RunSnapshot snapshot;
  /// The output writer's counters by name (rows of each CSV table at the snapshot).
  std::map<std::string, long long> counters;
  /// The ParaView series at the snapshot: (time or load parameter, file relative to the pvd).
  std::vector<std::pair<double, std::string>> series;
};

/// The file name of a run's checkpoint in its output directory.
inline constexpr const char* kCheckpointFile = "checkpoint.cbor";

/// Writes `checkpoint` to `path` atomically (binary CBOR; doubles exact). Throws OutputError.
void write_checkpoint(const std::string& path, const Checkpoint& checkpoint);

/// Reads a checkpoint written by write_checkpoint. Throws InputError naming `path` when it is
/// missing, not a sinew checkpoint, of another format version, or damaged.
Checkpoint read_checkpoint(const std::string& path);

/// A 64-bit hash of what makes two runs the same run: `scene_text` (the scene file and the
/// command-line overrides) and the model's meshes (rest positions, tets, regions) and unknowns.
std::uint64_t model_fingerprint(const Model& model, std::string_view scene_text);

/// A 64-bit hash of the model's meshes alone (rest positions and tets): what a later stage must
/// share with the run it starts from.
std::uint64_t mesh_fingerprint(const Model& model);

/// Throws InputError unless `snapshot` fits `model` (node, rigid-body and unknown counts, contact
/// bodies and surface nodes): `source` names the checkpoint in the message.
void check_snapshot_fits(const Model& model, const RunSnapshot& snapshot, const std::string& source);

}  // namespace sinew::model
