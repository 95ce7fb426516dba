#pragma once
/// @file run_output.hpp
/// What a static run writes into its output directory, every file atomically:
///   sinew.pvd              ParaView series of the increments
///   vtu/increment_NNNN.vtu displacement, region, J, von Mises stress per increment; with contact
///                          also material_depth, contact_force and contact_pressure per node
///   steps.csv              one row per accepted load step (lambda, Newton iterations, residual,
///                          energy, reaction force and moment of every constraint; with contact:
///                          pairs, area, max and mean penetration, contact energy, the force on
///                          body a from body b per pair "contact.<a>.<b>.f{x,y,z}" and, for
///                          self-contact, half the sum of nodal force magnitudes "contact.<a>.<a>.force";
///                          with the augmented Lagrangian "multiplier_updates" and
///                          "max_multiplier_pressure", with the adaptive penalty "contact.<a>.<b>.penalty"
///                          (the penalty after the step, which the next step uses); with friction
///                          "contact.<a>.<b>.friction_f{x,y,z}", the friction force on a from b)
///                          and, in the VTU files, friction_force and friction_slip (|slip| / slip
///                          threshold over the step: >= 1 sliding, < 1 sticking) per node
///   newton.csv             one row per Newton iteration
///   vtu/*.pvtu, vtu/*_pN.vtu on N > 1 MPI ranks, each increment (or output) as a parallel VTU set:
///                          rank N writes piece N (its share of the tets and surface triangles),
///                          rank 0 the .pvtu that lists them, and sinew.pvd refers to the .pvtu
///   last_converged.vtu     on failure or interrupt: the state the run could reach
///   checkpoint.cbor        the run's state after an accepted step, for --resume (run_checkpoints.hpp)
///   summary.json           status ("solved", "stopped", "output_error", "out_of_memory", "interrupted"),
///                          message, counts, time per phase
/// steps.csv and newton.csv are always written, with their header, even when no step converged.

#include <map>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "sinew/contact/contact_report.hpp"
#include "sinew/fem/problem.hpp"
#include "sinew/io/csv.hpp"
#include "sinew/io/vtu.hpp"
#include "sinew/scene/scene_config.hpp"
#include "sinew/model/checkpoint.hpp"
#include "sinew/model/model.hpp"
#include "sinew/solver/stepper.hpp"

namespace sinew::app {

/// Energies of a dynamic state (energy unit).
struct DynamicEnergies {
  double kinetic = 0;        ///< (1/2) vᵀ M v
  double elastic = 0;
  double gravitational = 0;  ///< potential of gravity and nodal loads
  double contact = 0;
  double total() const { return kinetic + elastic + gravitational + contact; }
};

class RunOutput {
 public:
  /// Creates nothing on disk until the first write.
  /// Reactions are the objective's gradient at the written state, so the model is not const:
  /// evaluating it refreshes the terms' bookkeeping (a no-op at the state Newton just accepted).
  RunOutput(std::string directory, model::Model& model, const scene::OutputConfig& config);

  void write_step(const solver::StepRecord& step, const fem::State& state);
  /// A newton.csv row: the step being attempted, its lambda or time, the iteration.
  void write_iteration(const solver::StepRecord& step, const solver::IterationRecord& iteration);
  /// VTU of increment k (if due per `every`), added to the .pvd series.
  void write_increment(int increment, int increments, const fem::State& state);
  void write_state(const std::string& file_name, const fem::State& state);
  // Dynamics: steps.csv has time and the energies instead of lambda; VTUs per output time carry
  // the velocity.
  void write_time_step(const solver::StepRecord& step, const fem::State& state, const NodalVectors& velocity);
  void write_output(int output, double time, const fem::State& state, const NodalVectors& velocity);
  /// Kinetic, elastic and gravitational energy of a state; the contact energy is taken from
  /// `contact` (the contact report of the same state) when the model has contact.
  DynamicEnergies energies(const fem::State& state, const NodalVectors& velocity,
                           const contact::ContactReport* contact) const;
  /// summary.json of a finished run, solved or stopped (keys of a static or a dynamic analysis).
  void write_summary(const solver::StepperResult& result, double wall_seconds, const std::string& scene_name);
  /// summary.json of a run stopped by something other than the solve (`status`: "output_error",
  /// "out_of_memory", "interrupted"), with the load parameter or time reached (`reached`), and,
  /// when a step was accepted (`last` not null), the counters, phase times and linear-solver
  /// counts up to the last accepted step (the time after it counts as "other"), under the keys of
  /// write_summary; the CSV logs are flushed first.
  void write_stopped_summary(const std::string& scene_name, const std::string& status, const std::string& message,
                             double reached, double wall_seconds, const solver::StepperSnapshot* last);

  /// Rows written so far to each CSV table, by table ("steps", "newton", "rigid_bodies"): what a
  /// checkpoint records so a resumed run goes on from the same rows.
  std::map<std::string, long long> counters() const;
  /// The ParaView series so far.
  const std::vector<std::pair<double, std::string>>& series() const { return series_->entries(); }
  /// Goes on from `checkpoint`: each CSV table keeps the rows the checkpoint counted (read from
  /// its file; later rows of the interrupted run go), the series the checkpoint's entries.
  /// Throws InputError when a table does not hold them.
  void resume(const model::Checkpoint& checkpoint);

  const std::string& directory() const { return directory_; }
  /// Seconds spent before solving (meshing, material depth, model set-up): the "setup" phase
  /// of summary.json, taken out of "other".
  void set_setup_seconds(double seconds) { setup_seconds_ = seconds; }

 private:
  io::VtuData vtu_data(const fem::State& state) const;
  /// Writes `data` as `stem`.vtu (one process), or on N > 1 MPI ranks as a parallel set: every
  /// rank its piece `stem`_p<rank>.vtu, then rank 0 `stem`.pvtu. Every rank must call it; when a
  /// rank's piece fails, every rank throws OutputError. Returns the file to add to the series
  /// (`stem` with its extension, relative to the output directory).
  std::string write_dataset(const std::string& stem, const io::VtuData& data) const;
  /// The counters of a static or dynamic run into summary.json (`reached`: lambda or time of
  /// `last_state`, the last accepted state).
  void put_counts(nlohmann::json& j, const solver::StepCounts& counts, double reached,
                  const fem::State& last_state) const;
  /// Rewrites steps.csv, newton.csv and rigid_bodies.csv with every row so far.
  void flush_tables() const;
  /// Adds the mesh sizes and the time per phase to `j` and writes summary.json.
  void finish_summary(nlohmann::json& j, double wall_seconds, const solver::PhaseTimes& times,
                      const solver::LinearCounts& linear) const;
  /// Contact figures of `state` (contact::contact_report; the model's contact energy is not
  /// changed), none without contact.
  std::optional<contact::ContactReport> contact_statistics(const fem::State& state) const;
  /// Adds a steps.csv row with the reactions and the contact figures `contact` (of the same
  /// state); `flush` rewrites the file now.
  void write_row(std::vector<io::CsvTable::Cell> row, const fem::State& state,
                 const contact::ContactReport* contact, bool flush = true);
  /// Adds a rigid_bodies.csv row: `row` (step, increment or time, ...) then, per rigid body, the
  /// current position of its reference point (the mean of its nodes at rest) and its rotation
  /// (vector, radians; angle, degrees).
  void write_rigid_row(std::vector<io::CsvTable::Cell> row, const fem::State& state, bool flush);
  std::string directory_;
  double setup_seconds_ = 0;
  /// On several ranks, static runs: the elastic energy summed over the ranks at the last row
  /// written (write_row), for a summary that only rank 0 may reach (energy).
  double last_elastic_energy_ = 0;
  const fem::Problem& problem_;
  model::Model& model_;
  scene::OutputConfig config_;
  std::unique_ptr<io::CsvTable> steps_;
  std::unique_ptr<io::CsvTable> newton_;
  /// rigid_bodies.csv: pose of every rigid body per accepted step (none without rigid bodies).
  std::unique_ptr<io::CsvTable> rigid_;
  std::unique_ptr<io::PvdSeries> series_;
  std::vector<std::string> reaction_names_;
  /// Augmented Lagrangian: the step's multiplier updates and the largest nodal pressure
  /// ("multiplier_updates", "max_multiplier_pressure") after the step's base columns.
  void add_multiplier_cells(const solver::StepRecord& step, std::vector<io::CsvTable::Cell>& row) const;
  bool log_multiplier_updates_ = false;
  bool log_penalties_ = false;  ///< adaptive penalty: "contact.<a>.<b>.penalty" per pair
  std::vector<std::pair<Index, Index>> contact_columns_;  ///< body pairs with contact, in column order
};

}  // namespace sinew::app
