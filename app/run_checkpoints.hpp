#pragma once
/// @file run_checkpoints.hpp
/// The checkpoints of a run (docs/checkpoints.md): the latest snapshot is kept after every
/// accepted step, and written to <output>/checkpoint.cbor when due (output.checkpoint_every),
/// at the end, and on an interrupt.

#include <cstdint>
#include <optional>
#include <string>

#include "run_output.hpp"
#include "sinew/model/checkpoint.hpp"

namespace sinew::app {

class RunCheckpoints {
 public:
  /// `every`: write after every n-th accepted load step (static) or output interval (dynamic);
  /// 0 never when due. `model` and `output` must outlive this.
  RunCheckpoints(const model::Model& model, const RunOutput& output, int every, std::uint64_t fingerprint);

  /// After an accepted step, once the outputs of the step are written: keeps the snapshot and
  /// writes it when due. In dynamics a checkpoint is due only at an output time, when the CSV
  /// tables on disk hold every row it counts.
  void on_accepted(const solver::StepperSnapshot& snapshot);
  /// Writes the latest snapshot unless it was written, marked as the end of a finished run when
  /// `finished` (a later stage may start from it: docs/stages.md); false when no step was
  /// accepted.
  bool write_latest(bool finished = false);
  /// The latest snapshot, or null before the first accepted step.
  const model::RunSnapshot* latest() const { return latest_ ? &latest_->snapshot : nullptr; }
  std::string path() const;

 private:
  const model::Model& model_;
  const RunOutput& output_;
  int every_;
  std::uint64_t fingerprint_;
  std::uint64_t mesh_fingerprint_;
  std::optional<model::Checkpoint> latest_;
  bool latest_written_ = false;
};

}  // namespace sinew::app
