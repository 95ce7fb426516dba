#include "convergence_study.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "run_scene.hpp"
#include "sinew/contact/contact_report.hpp"
#include "sinew/io/output_directory.hpp"
#include "sinew/core/error.hpp"
#include "sinew/core/log.hpp"
#include "sinew/io/atomic_file.hpp"
#include "sinew/io/csv.hpp"
#include "sinew/model/model.hpp"

namespace sinew::app {

namespace {

namespace fs = std::filesystem;

/// Contact energy of the model's geometry for measuring: area method, unit penalty on every
/// pair the scene has contact on (the penetration figures do not depend on the penalty).
contact::ContactEnergy measuring_contact(const model::Model& model) {
  return contact::ContactEnergy(model::geometry_with_penalty(*model.contact_setup, 1.0), contact::ContactOptions{});
}

/// Lowers the log level to warnings for its lifetime and restores it, also when a run throws.
class QuietLog {
 public:
  QuietLog() : level_(logger().level()) { logger().set_level(spdlog::level::warn); }
  ~QuietLog() { logger().set_level(level_); }
  QuietLog(const QuietLog&) = delete;
  QuietLog& operator=(const QuietLog&) = delete;

 private:
  spdlog::level::level_enum level_;
};

std::string penalty_label(double penalty) { return fmt::format("{:g}", penalty); }

void check_options(const scene::SceneConfig& scene, const model::Model& model, const ConvergenceStudyOptions& o) {
  const fem::Problem& problem = *model.problem;
  if (o.penalties.empty()) throw InputError("study convergence: no penalties given");
  for (double p : o.penalties)
    if (!(p >= 0) || !std::isfinite(p))
      throw InputError(fmt::format("study convergence: penalty {} must be finite and >= 0", p));
    else if (p > 0)
      model::geometry_with_penalty(*model.contact_setup, p);  // throws for a penalty too stiff for Newton
  if (o.methods.empty()) throw InputError("study convergence: no contact methods given");
  if (!(o.tolerance > 0 && o.tolerance < 1))
    throw InputError(fmt::format("study convergence: tolerance {} must be in (0, 1)", o.tolerance));
  if (!(o.end_time >= 0) || !std::isfinite(o.end_time))
    throw InputError(fmt::format("study convergence: end time {} must be finite and >= 0", o.end_time));
  if (o.end_time > 0 && !scene.dynamics.enabled)
    throw InputError("study convergence: --end-time needs a scene with a dynamics section");
  if (!o.sweep_body.empty()) {
    const bool known = std::any_of(problem.bodies.begin(), problem.bodies.end(),
                                   [&](const fem::BodyRange& b) { return b.name == o.sweep_body; });
    if (!known) {
      std::string names;
      for (const auto& b : problem.bodies) names += (names.empty() ? "" : ", ") + b.name;
      throw InputError(fmt::format("study convergence: sweep body \"{}\" is not in the scene (bodies: {})",
                                   o.sweep_body, names));
    }
    if (o.sweep_positions < 2)
      throw InputError(fmt::format("study convergence: {} sweep positions (need at least 2)", o.sweep_positions));
    if (!o.sweep_translation.allFinite() || o.sweep_translation.norm() == 0 || !o.sweep_from.allFinite())
      throw InputError("study convergence: the sweep translation must be finite and non-zero, its start finite");
    if (!(o.sweep_penalty > 0) || !std::isfinite(o.sweep_penalty))
      throw InputError(fmt::format("study convergence: sweep penalty {} must be finite and > 0", o.sweep_penalty));
  }
}

/// Contact forces on the sweep body's nodes at each position of its rigid translation.
void write_force_sweep(const model::Model& model, const ConvergenceStudyOptions& o) {
  const fem::Problem& problem = *model.problem;
  const auto body = std::find_if(problem.bodies.begin(), problem.bodies.end(),
                                 [&](const fem::BodyRange& b) { return b.name == o.sweep_body; });
  io::CsvTable forces(o.output_directory + "/sweep_forces.csv",
                      {"method", "position", "offset", "node", "x", "y", "z", "fx", "fy", "fz"});
  io::CsvTable totals(o.output_directory + "/sweep_totals.csv",
                      {"method", "position", "offset", "fx", "fy", "fz", "energy"});
  const double length = o.sweep_translation.norm();
  for (const auto method : o.methods) {
    contact::ContactOptions options = model.contact_setup->options;
    options.method = method;
    contact::ContactEnergy energy(model::geometry_with_penalty(*model.contact_setup, o.sweep_penalty), options);
    for (int k = 0; k < o.sweep_positions; ++k) {
      const double s = static_cast<double>(k) / (o.sweep_positions - 1);
      Positions x = problem.mesh.rest;
      for (Index v = body->first_node; v < body->first_node + body->num_nodes; ++v)
        x.row(v) += (o.sweep_from + s * o.sweep_translation).transpose();
      energy.begin_step(x);
      const contact::ContactReport stats = contact::contact_report(energy, x);
      Vector3 total = Vector3::Zero();
      for (Index v = body->first_node; v < body->first_node + body->num_nodes; ++v) {
        const Vector3 f = stats.nodal_force.row(v).transpose();
        total += f;
        if (f.norm() == 0) continue;
        forces.append({contact_method_name(method), static_cast<long long>(k), s * length, static_cast<long long>(v),
                       x(v, 0), x(v, 1), x(v, 2), f.x(), f.y(), f.z()});
      }
      totals.append({contact_method_name(method), static_cast<long long>(k), s * length, total.x(), total.y(),
                     total.z(), stats.energy});
    }
  }
  forces.flush();
  totals.flush();
  nlohmann::json meta;
  meta["body"] = o.sweep_body;
  meta["first_node"] = body->first_node;
  meta["num_nodes"] = body->num_nodes;
  meta["from"] = {o.sweep_from.x(), o.sweep_from.y(), o.sweep_from.z()};
  meta["translation"] = {o.sweep_translation.x(), o.sweep_translation.y(), o.sweep_translation.z()};
  meta["positions"] = o.sweep_positions;
  meta["penalty"] = o.sweep_penalty;
  io::write_file_atomically(o.output_directory + "/sweep.json", meta.dump(2) + "\n");
}

}  // namespace

std::string contact_method_name(contact::ContactMethod method) {
  return std::string(name_of(method));
}

ConvergenceStudyReport run_convergence_study(const scene::SceneConfig& scene, const ConvergenceStudyOptions& o) {
  // Everything that can fail on bad input happens before the first file is written.
  if (!scene.contact.enabled)
    throw InputError(fmt::format("study convergence: scene \"{}\" has no contact section", scene.name));
  model::Model model = model::build_model(scene);  // meshes and material depth, once for every run
  check_options(scene, model, o);
  if (o.end_time > 0) model.dynamics->options.end_time = o.end_time;
  contact::ContactEnergy measure = measuring_contact(model);
  const io::OutputDirectoryLock lock(o.output_directory, {.overwrite = o.overwrite}, o.command);

  ConvergenceStudyReport report;
  io::CsvTable residuals(o.output_directory + "/residuals.csv",
                         {"method", "penalty", "total_iteration", "step", "time", "iteration", "residual",
                          "equilibrium_residual"});
  for (const auto method : o.methods) {
    for (const double penalty : o.penalties) {
      model::set_contact(model, {.method = method, .penalty = penalty});
      ConvergenceRun run;
      run.method = method;
      run.penalty = penalty;
      run.directory = contact_method_name(method) + "-eps" + penalty_label(penalty);
      RunOptions options;
      options.output_directory = o.output_directory + "/" + run.directory;
      options.progress_bar = false;
      options.log_steps = false;
      long long total_iterations = 0;
      bool first = true;
      options.on_iteration = [&](int step, double time, const solver::IterationRecord& it) {
        total_iterations += it.iteration > 0 ? 1 : 0;
        residuals.append({contact_method_name(method), penalty, total_iterations, static_cast<long long>(step), time,
                          static_cast<long long>(it.iteration), it.residual, it.equilibrium_residual});
        if (first) run.first_residual = it.equilibrium_residual;
        first = false;
        run.largest_residual = std::max(run.largest_residual, it.equilibrium_residual);
        run.final_residual = it.equilibrium_residual;
      };
      RunReport result;
      {
        const QuietLog quiet;  // the study prints its own table
        result = run_model(model, scene.output, options);  // the set-up is shared: not part of a run
      }
      residuals.flush();
      run.solved = result.success;
      run.message = result.message;
      run.wall_seconds = result.wall_seconds;
      run.steps = result.result.steps;
      run.newton_iterations = result.result.newton_iterations;
      run.cuts = result.result.cuts;
      const fem::State& last = result.result.last_state;
      measure.begin_step(last.x);
      run.max_penetration = contact::contact_report(measure, last.x).max_penetration;
      // A run that never needed a Newton iteration started in equilibrium (within the solver's
      // tolerance): there is nothing to reduce.
      run.converged = run.solved && (run.newton_iterations == 0 || run.final_residual <= o.tolerance * run.largest_residual);
      if (o.progress)
        logger().info("{:5s} eps {:>6s}: {} ({} steps, {} Newton iterations, {} cuts), equilibrium residual {:.3e} -> "
                      "{:.3e}, {}, max penetration {:.4g}, {:.1f} s",
                      contact_method_name(method), penalty_label(penalty), run.solved ? "solved" : "FAILED", run.steps,
                      run.newton_iterations, run.cuts, run.largest_residual, run.final_residual,
                      run.converged ? "converged" : "not converged", run.max_penetration, run.wall_seconds);
      report.runs.push_back(std::move(run));
    }
  }

  io::CsvTable runs(o.output_directory + "/runs.csv",
                    {"method", "penalty", "solved", "converged", "steps", "newton_iterations", "cuts",
                     "first_residual", "largest_residual", "final_residual", "max_penetration", "wall_seconds",
                     "directory", "message"});
  for (const auto& r : report.runs)
    runs.append({contact_method_name(r.method), r.penalty, static_cast<long long>(r.solved),
                 static_cast<long long>(r.converged), static_cast<long long>(r.steps),
                 static_cast<long long>(r.newton_iterations), static_cast<long long>(r.cuts), r.first_residual,
                 r.largest_residual, r.final_residual, r.max_penetration, r.wall_seconds, r.directory, r.message});
  runs.flush();
  io::write_file_atomically(o.output_directory + "/penetration.md", penetration_table_markdown(report, o.methods));
  if (!o.sweep_body.empty()) write_force_sweep(model, o);
  return report;
}

std::string penetration_table_markdown(const ConvergenceStudyReport& report,
                                       const std::vector<contact::ContactMethod>& methods) {
  std::vector<double> penalties;
  for (const auto& r : report.runs)
    if (std::find(penalties.begin(), penalties.end(), r.penalty) == penalties.end()) penalties.push_back(r.penalty);
  std::sort(penalties.begin(), penalties.end());
  std::string text = "| penalty ε |";
  std::string rule = "|---:|";
  for (const auto m : methods) {
    text += fmt::format(" {} |", m == contact::ContactMethod::Area ? "area integration" : "point collocation");
    rule += "---:|";
  }
  text += "\n" + rule + "\n";
  for (const double p : penalties) {
    text += fmt::format("| {} |", penalty_label(p));
    for (const auto m : methods) {
      const auto run = std::find_if(report.runs.begin(), report.runs.end(),
                                    [&](const ConvergenceRun& r) { return r.method == m && r.penalty == p; });
      if (run == report.runs.end())
        text += " |";
      else if (!run->solved)
        text += fmt::format(" — (failed; {:.3f} when it stopped) |", run->max_penetration);
      else
        text += fmt::format(" {:.3f}{} |", run->max_penetration, run->converged ? "" : " (not converged)");
    }
    text += "\n";
  }
  return text;
}

}  // namespace sinew::app
