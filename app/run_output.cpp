#include "run_output.hpp"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "sinew/core/error.hpp"
#include "sinew/fem/reactions.hpp"
#include "sinew/io/atomic_file.hpp"
#include "sinew/io/pvtu.hpp"
#include "sinew/parallel/partition.hpp"
#include "sinew/parallel/ranks.hpp"

namespace sinew::app {

RunOutput::RunOutput(std::string directory, model::Model& model, const scene::OutputConfig& config)
    : directory_(std::move(directory)), problem_(*model.problem), model_(model), config_(config) {
  const fem::Problem& problem = problem_;
  std::vector<std::string> columns =
      model.is_dynamic() ? std::vector<std::string>{"step", "time", "step_size", "newton_iterations", "residual", "cuts",
                                            "kinetic_energy", "elastic_energy", "gravitational_energy",
                                            "contact_energy", "total_energy"}
                 : std::vector<std::string>{"step", "increment", "lambda", "step_size", "newton_iterations",
                                            "residual", "force_scale", "energy", "cuts"};
  const auto enforcement = model.contact ? model.contact_enforcement.method : contact::ContactEnforcement::Penalty;
  log_multiplier_updates_ = enforcement == contact::ContactEnforcement::AugmentedLagrangian;
  log_penalties_ = enforcement == contact::ContactEnforcement::AdaptivePenalty;
  if (log_multiplier_updates_) {
    columns.emplace_back("multiplier_updates");
    columns.emplace_back("max_multiplier_pressure");
  }
  for (const auto& p : problem.prescribed) reaction_names_.push_back(p.name);
  for (const auto& p : problem.planar) reaction_names_.push_back(p.name);
  for (const auto& r : problem.rigid_bodies) reaction_names_.push_back(r.name);
  for (const auto& name : reaction_names_)
    for (const char* c : {"fx", "fy", "fz", "mx", "my", "mz"}) columns.push_back(name + "." + c);
  if (model.contact) {
    for (const char* c : {"contact_pairs", "contact_area", "max_penetration", "mean_penetration"})
      columns.emplace_back(c);
    if (!model.is_dynamic()) columns.emplace_back("contact_energy");  // dynamics logs it with the other energies
    const auto& names = model.contact_body_names();
    const auto& penalty = model.contact->geometry().penalty;
    for (Index a = 0; a < penalty.rows(); ++a)
      for (Index b = a; b < penalty.cols(); ++b) {
        if (penalty(a, b) <= 0) continue;
        contact_columns_.emplace_back(a, b);
        const std::string prefix = "contact." + names[static_cast<std::size_t>(a)] + "." + names[static_cast<std::size_t>(b)];
        if (a == b) {
          columns.push_back(prefix + ".force");
        } else {
          for (const char* c : {".fx", ".fy", ".fz"}) columns.push_back(prefix + c);
        }
        columns.push_back(prefix + ".max_penetration");
        if (log_penalties_) columns.push_back(prefix + ".penalty");
        if (model.friction && a != b)
          for (const char* c : {".friction_fx", ".friction_fy", ".friction_fz"}) columns.push_back(prefix + c);
      }
  }
  steps_ = std::make_unique<io::CsvTable>(directory_ + "/steps.csv", columns);
  newton_ = std::make_unique<io::CsvTable>(
      directory_ + "/newton.csv",
      std::vector<std::string>{"step", "lambda", "iteration", "residual", "force_scale", "energy", "step_length",
                               "line_search_halvings", "linear_iterations", "increment", "regularization",
                               "equilibrium_residual"});
  series_ = std::make_unique<io::PvdSeries>(directory_ + "/sinew.pvd");
  if (!problem.rigid_bodies.empty()) {
    std::vector<std::string> rigid_columns =
        model.is_dynamic() ? std::vector<std::string>{"step", "time"} : std::vector<std::string>{"step", "increment", "lambda"};
    for (const auto& r : problem.rigid_bodies)
      for (const char* c : {"x", "y", "z", "rx", "ry", "rz", "angle_deg"}) rigid_columns.push_back(r.name + "." + c);
    rigid_ = std::make_unique<io::CsvTable>(directory_ + "/rigid_bodies.csv", rigid_columns);
  }
}

void RunOutput::write_rigid_row(std::vector<io::CsvTable::Cell> row, const fem::State& state, bool flush) {
  if (!rigid_) return;
  for (std::size_t r = 0; r < problem_.rigid_bodies.size(); ++r) {
    const fem::RigidPose& pose = state.rigid.at(r);
    const Vector3 center = model_.dofs->rigid_center(r) + pose.t;
    const Eigen::AngleAxisd rotation(pose.R);
    const Vector3 vector = rotation.angle() * rotation.axis();
    for (int k = 0; k < 3; ++k) row.emplace_back(center[k]);
    for (int k = 0; k < 3; ++k) row.emplace_back(vector[k]);
    row.emplace_back(rotation.angle() * 180.0 / M_PI);
  }
  if (flush)
    rigid_->add_row(row);
  else
    rigid_->append(row);
}

std::optional<contact::ContactReport> RunOutput::contact_statistics(const fem::State& state) const {
  if (!model_.contact) return std::nullopt;
  return contact::contact_report(*model_.contact, state.x);
}

void RunOutput::write_step(const solver::StepRecord& step, const fem::State& state) {
  const auto contact = contact_statistics(state);
  std::vector<io::CsvTable::Cell> row{static_cast<long long>(step.step), static_cast<long long>(step.segment), step.t,
                                      step.step_size, static_cast<long long>(step.newton_iterations), step.residual,
                                      step.force_scale, step.energy, static_cast<long long>(step.cuts)};
  add_multiplier_cells(step, row);
  write_row(std::move(row), state, contact ? &*contact : nullptr);
  write_rigid_row({static_cast<long long>(step.step), static_cast<long long>(step.segment), step.t}, state,
                  true);
}

DynamicEnergies RunOutput::energies(const fem::State& state, const NodalVectors& velocity,
                                    const contact::ContactReport* contact) const {
  DynamicEnergies e;
  const VectorX v = velocity.reshaped<Eigen::RowMajor>();  // node-major x, y, z
  e.kinetic = 0.5 * v.dot(model_.dynamics->mass->multiply(v));
  e.elastic = parallel::sum(model_.elastic->value(state.x));  // on several ranks each holds its tets
  e.gravitational = model_.external->value(state.x);
  if (contact) e.contact = contact->energy;
  return e;
}

void RunOutput::write_time_step(const solver::StepRecord& step, const fem::State& state,
                                const NodalVectors& velocity) {
  const auto contact = contact_statistics(state);
  const DynamicEnergies e = energies(state, velocity, contact ? &*contact : nullptr);
  std::vector<io::CsvTable::Cell> row{static_cast<long long>(step.step), step.t, step.step_size,
                                      static_cast<long long>(step.newton_iterations), step.residual,
                                      static_cast<long long>(step.cuts), e.kinetic, e.elastic, e.gravitational,
                                      e.contact, e.total()};
  add_multiplier_cells(step, row);
  write_row(std::move(row), state, contact ? &*contact : nullptr, /*flush=*/false);
  write_rigid_row({static_cast<long long>(step.step), step.t}, state, /*flush=*/false);
}

void RunOutput::write_output(int output, double time, const fem::State& state, const NodalVectors& velocity) {
  // Time steps are many: the CSV files are rewritten at output times, not after every step.
  steps_->flush();
  newton_->flush();
  if (rigid_) rigid_->flush();
  if (!config_.vtu) return;
  io::VtuData data = vtu_data(state);
  data.point_fields.push_back({"velocity", MatrixX(velocity)});
  series_->add(time, write_dataset(fmt::format("vtu/output_{:04d}", output), data));
}

void RunOutput::add_multiplier_cells(const solver::StepRecord& step, std::vector<io::CsvTable::Cell>& row) const {
  if (!log_multiplier_updates_) return;
  const VectorX& pressure = model_.contact->pressure();
  row.emplace_back(static_cast<long long>(step.refinements));
  row.emplace_back(pressure.size() > 0 ? pressure.maxCoeff() : 0.0);
}

void RunOutput::write_row(std::vector<io::CsvTable::Cell> row, const fem::State& state,
                          const contact::ContactReport* contact, bool flush) {
  const auto gradient = model_.objective->full_gradient(state);
  // For the stabilization ratio of a static run's summary (every rank is here).
  if (parallel::size() > 1 && !model_.is_dynamic()) last_elastic_energy_ = parallel::sum(model_.elastic->value(state.x));
  for (const auto& reaction : fem::compute_reactions(problem_, *model_.dofs, state, gradient)) {
    for (int k = 0; k < 3; ++k) row.emplace_back(reaction.force[k]);
    for (int k = 0; k < 3; ++k) row.emplace_back(reaction.moment[k]);
  }
  if (contact) {
    const contact::ContactReport& c = *contact;
    row.emplace_back(static_cast<long long>(c.pairs));
    row.emplace_back(c.area);
    row.emplace_back(c.max_penetration);
    row.emplace_back(c.mean_penetration);
    if (!model_.is_dynamic()) row.emplace_back(c.energy);
    const std::vector<Vector3> friction =
        model_.friction ? model_.friction->body_pair_forces(state.x) : std::vector<Vector3>{};
    const Index bodies = model_.contact->num_bodies();
    for (const auto& [a, b] : contact_columns_) {
      if (a == b) {
        row.emplace_back(c.self_contact_force_magnitude[a]);
      } else {
        const Vector3& f = c.force_between(a, b);
        for (int k = 0; k < 3; ++k) row.emplace_back(f[k]);
      }
      row.emplace_back(c.max_penetration_between(a, b));
      if (log_penalties_) row.emplace_back(model_.contact->geometry().penalty(a, b));
      if (model_.friction && a != b)
        for (int k = 0; k < 3; ++k) row.emplace_back(friction[static_cast<std::size_t>(a * bodies + b)][k]);
    }
  }
  if (flush) {
    steps_->add_row(row);
    newton_->flush();
  } else {
    steps_->append(row);
  }
}

std::map<std::string, long long> RunOutput::counters() const {
  std::map<std::string, long long> counts{{"steps", static_cast<long long>(steps_->rows())},
                                          {"newton", static_cast<long long>(newton_->rows())}};
  if (rigid_) counts["rigid_bodies"] = static_cast<long long>(rigid_->rows());
  return counts;
}

void RunOutput::resume(const model::Checkpoint& checkpoint) {
  auto rows = [&](const char* table) -> std::size_t {
    const auto it = checkpoint.counters.find(table);
    if (it == checkpoint.counters.end() || it->second < 0)
      throw InputError(fmt::format("cannot resume: the checkpoint does not count the rows of {}", table));
    return static_cast<std::size_t>(it->second);
  };
  steps_->restore(rows("steps"));
  newton_->restore(rows("newton"));
  if (rigid_) rigid_->restore(rows("rigid_bodies"));
  series_->restore(checkpoint.series);
  if (parallel::size() > 1 && !model_.is_dynamic())  // every rank resumes
    last_elastic_energy_ = parallel::sum(model_.elastic->value(checkpoint.snapshot.stepper.state.x));
}

void RunOutput::flush_tables() const {
  steps_->flush();
  newton_->flush();
  if (rigid_) rigid_->flush();
}

void RunOutput::write_iteration(const solver::StepRecord& step, const solver::IterationRecord& it) {
  newton_->append({static_cast<long long>(step.step), step.t, static_cast<long long>(it.iteration), it.residual,
                   it.force_scale, it.energy, it.step_length, static_cast<long long>(it.line_search_steps),
                   static_cast<long long>(it.linear_iterations), it.increment, it.regularization,
                   it.equilibrium_residual});
}

io::VtuData RunOutput::vtu_data(const fem::State& state) const {
  io::VtuData data;
  data.points = state.x;
  data.tets = problem_.mesh.tets;
  data.point_fields.push_back({"displacement", MatrixX(state.x - problem_.mesh.rest)});
  const auto measures = fem::compute_tet_measures(state.x, *model_.elastic);
  data.cell_fields.push_back({"J", MatrixX(measures.J)});
  data.cell_fields.push_back({"von_mises_stress", MatrixX(measures.von_mises)});
  data.int_cell_fields.emplace_back("region", problem_.mesh.region);
  IndexVector rigid(problem_.mesh.num_tets());
  for (Index t = 0; t < problem_.mesh.num_tets(); ++t) rigid[t] = fem::is_rigid_tet(problem_, t) ? 1 : 0;
  data.int_cell_fields.emplace_back("rigid", rigid);
  if (model_.contact) {
    const contact::ContactReport c = contact::contact_report(*model_.contact, state.x);
    data.point_fields.push_back({"material_depth", MatrixX(model_.contact->geometry().depth)});
    data.point_fields.push_back({"contact_force", MatrixX(c.nodal_force)});
    data.point_fields.push_back({"contact_pressure", MatrixX(c.nodal_pressure)});
    if (model_.friction) {
      NodalVectors gradient = NodalVectors::Zero(state.x.rows(), 3);
      model_.friction->add_gradient(state.x, gradient);
      data.point_fields.push_back({"friction_force", MatrixX(-gradient)});
      data.point_fields.push_back({"friction_slip", MatrixX(model_.friction->slip_ratio(state.x))});
    }
  }
  return data;
}

std::string RunOutput::write_dataset(const std::string& stem, const io::VtuData& data) const {
  const int ranks = parallel::size();
  if (ranks <= 1) {
    io::write_vtu(directory_ + "/" + stem + ".vtu", data);
    return stem + ".vtu";
  }
  // Each rank writes the cells it owns (the tets of its part of the mesh, Model::tet_owner, and
  // the triangles whose first node it owns); a failure anywhere stops every rank at the same point
  // (a .pvtu is written only when all its pieces are).
  const std::filesystem::path folder = (std::filesystem::path(directory_) / stem).parent_path();
  const std::string base = std::filesystem::path(stem).filename().string();
  const auto piece_name = [&](int rank) { return fmt::format("{}_p{}.vtu", base, rank); };
  const int rank = parallel::rank();
  std::string failure;
  try {
    const std::vector<int>& tet_owner = model_.tet_owner;
    const std::vector<int> node_owner = parallel::node_owners(data.tets, tet_owner, data.points.rows());
    std::vector<Index> tets, triangles;
    for (Index t = 0; t < data.tets.rows(); ++t)
      if (tet_owner.at(static_cast<std::size_t>(t)) == rank) tets.push_back(t);
    for (Index f = 0; f < data.triangles.rows(); ++f)
      if (node_owner.at(static_cast<std::size_t>(data.triangles(f, 0))) == rank) triangles.push_back(f);
    const io::VtuData piece = io::vtu_piece(data, tets, triangles);
    const io::WritingOnThisRank writing;
    io::write_vtu((folder / piece_name(rank)).string(), piece);
  } catch (const std::exception& e) {
    failure = e.what();
  }
  const int failed_rank = static_cast<int>(parallel::max(failure.empty() ? -1.0 : static_cast<double>(rank)));
  if (failed_rank >= 0)
    throw OutputError(!failure.empty()
                          ? failure
                          : fmt::format("cannot write the parallel VTU set {}/{}.pvtu: MPI rank {} could not write its "
                                        "piece {} (that rank prints why)",
                                        directory_, stem, failed_rank, (folder / piece_name(failed_rank)).string()));
  std::vector<std::string> pieces;
  for (int r = 0; r < ranks; ++r) pieces.push_back(piece_name(r));
  io::write_pvtu(directory_ + "/" + stem + ".pvtu", data, pieces);  // rank 0 only (files_written)
  return stem + ".pvtu";
}

void RunOutput::write_state(const std::string& file_name, const fem::State& state) {
  io::write_vtu(directory_ + "/" + file_name, vtu_data(state));
}

void RunOutput::write_increment(int increment, int increments, const fem::State& state) {
  if (!config_.vtu) return;
  const int every = std::max(1, config_.every);
  if (increment % every != 0 && increment != increments) return;
  series_->add(state.lambda, write_dataset(fmt::format("vtu/increment_{:04d}", increment), vtu_data(state)));
}

void RunOutput::finish_summary(nlohmann::json& j, double wall_seconds, const solver::PhaseTimes& times,
                               const solver::LinearCounts& linear) const {
  j["factorizations"] = linear.factorizations;
  j["linear_iterations"] = linear.linear_iterations;
  j["undone_lagged_steps"] = linear.undone_lagged_steps;
  j["nodes"] = problem_.mesh.num_nodes();
  j["tets"] = problem_.mesh.num_tets();
  j["dofs"] = model_.dofs->num_dofs();
  j["wall_seconds"] = wall_seconds;
  j["seconds"] = {{"setup", setup_seconds_},
                  {"forces_and_stiffness", times.forces_and_stiffness},
                  {"collision", times.collision},
                  {"linear_solve", times.linear_solve},
                  {"line_search", times.line_search},
                  {"other", std::max(0.0, wall_seconds - setup_seconds_ - times.total())}};
  io::write_file_atomically(directory_ + "/summary.json", j.dump(2) + "\n");
}

void RunOutput::put_counts(nlohmann::json& j, const solver::StepCounts& counts, double reached,
                           const fem::State& last_state) const {
  if (model_.is_dynamic()) {
    j["time_reached"] = reached;
    j["steps"] = counts.steps;
    j["newton_iterations"] = counts.newton_iterations;
    j["step_cuts"] = counts.cuts;
    j["outputs"] = counts.segments_completed + 1;  // the start state included
    j["min_time_step"] = counts.min_step;
    j["max_time_step"] = counts.max_step;
  } else {
    j["lambda_reached"] = reached;
    j["increments_completed"] = counts.segments_completed;
    j["steps"] = counts.steps;
    j["newton_iterations"] = counts.newton_iterations;
    j["step_cuts"] = counts.cuts;
    j["snap_throughs"] = counts.snap_throughs;
    j["multiplier_updates"] = counts.refinements;
    // Viscous stabilization (solver.stabilization): steps taken with it and the energy its
    // forces dissipated, against the energy stored at the end (their ratio should stay small).
    j["stabilized_steps"] = counts.stabilized_steps;
    j["stabilization_dissipated_energy"] = counts.dissipated;
    // On several ranks each holds its own tets' energy, and a stopped run may write this on one
    // rank alone: the sum recorded with the last step's row stands for it (the same state).
    const double stored = counts.stabilized_steps == 0 ? 0.0
                          : parallel::size() > 1   ? last_elastic_energy_
                                                   : model_.elastic->value(last_state.x);
    j["stabilization_energy_ratio"] = stored > 0 ? counts.dissipated / stored : 0.0;
  }
}

void RunOutput::write_summary(const solver::StepperResult& result, double wall_seconds, const std::string& scene_name) {
  flush_tables();
  nlohmann::json j;
  j["scene"] = scene_name;
  j["success"] = result.success;
  j["status"] = result.success ? "solved" : "stopped";
  j["message"] = result.message;
  put_counts(j, solver::counts_of(result), model_.is_dynamic() ? result.t : result.last_state.lambda,
             result.last_state);
  finish_summary(j, wall_seconds, result.times, result.linear);
}

void RunOutput::write_stopped_summary(const std::string& scene_name, const std::string& status,
                                      const std::string& message, double reached, double wall_seconds,
                                      const solver::StepperSnapshot* last) {
  try {
    flush_tables();
  } catch (const Error&) {  // the summary below may still fit
  }
  nlohmann::json j;
  j["scene"] = scene_name;
  j["success"] = false;
  j["status"] = status;
  j["message"] = message;
  if (last)
    put_counts(j, last->counts, reached, last->state);
  else
    j[model_.is_dynamic() ? "time_reached" : "lambda_reached"] = reached;
  finish_summary(j, wall_seconds, last ? last->times : solver::PhaseTimes{},
                 last ? last->linear : solver::LinearCounts{});
}

}  // namespace sinew::app
