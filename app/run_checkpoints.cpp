#include "run_checkpoints.hpp"

namespace sinew::app {

RunCheckpoints::RunCheckpoints(const model::Model& model, const RunOutput& output, int every,
                               std::uint64_t fingerprint)
    : model_(model),
      output_(output),
      every_(every),
      fingerprint_(fingerprint),
      mesh_fingerprint_(model::mesh_fingerprint(model)) {}

std::string RunCheckpoints::path() const { return output_.directory() + "/" + model::kCheckpointFile; }

void RunCheckpoints::on_accepted(const solver::StepperSnapshot& snapshot) {
  if (!latest_) latest_.emplace();
  latest_->fingerprint = fingerprint_;
  latest_->mesh_fingerprint = mesh_fingerprint_;
  latest_->finished = false;
  latest_->snapshot = model::take_snapshot(model_, snapshot);
  latest_->counters = output_.counters();
  latest_->series = output_.series();
  latest_written_ = false;
  if (every_ <= 0) return;
  const bool due = model_.is_dynamic()
                       ? snapshot.segment_done && snapshot.counts.segments_completed % every_ == 0
                       : snapshot.counts.steps % every_ == 0;
  if (due) write_latest();
}

bool RunCheckpoints::write_latest(bool finished) {
  if (!latest_) return false;
  if (finished && !latest_->finished) {
    latest_->finished = true;
    latest_written_ = false;
  }
  if (!latest_written_) model::write_checkpoint(path(), *latest_);
  latest_written_ = true;
  return true;
}

}  // namespace sinew::app
