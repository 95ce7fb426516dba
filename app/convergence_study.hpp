#pragma once
/// @file convergence_study.hpp
/// `sinew study convergence`: the dissertation's §6.5 study on any scene with contact. The scene
/// is solved once per contact method (area integration, point collocation) and penalty ε; the
/// study records the residual of every Newton iteration in sequence (Figs. 31–35), whether each
/// run reached equilibrium, and the maximum penetration at the end (Table 1). Optionally, one
/// body is swept rigidly through the others and the contact forces on its nodes are recorded
/// per position and method (Figs. 29–30).
///
/// Files written to the output directory:
///   residuals.csv      method, penalty, total_iteration, step, time, iteration, residual,
///                      equilibrium_residual: every Newton iteration of every run, in order
///   runs.csv           one row per run: solved, converged, steps, Newton iterations, cuts,
///                      first and final equilibrium residual, maximum penetration, seconds
///   penetration.md     Table 1: maximum penetration against ε, one column per method
///   sweep_forces.csv   (with a sweep) method, position, offset, node (global), x, y, z, fx, fy, fz
///                      for every node of the swept body with a contact force
///   sweep_totals.csv   (with a sweep) method, position, offset, fx, fy, fz (sum over the body), energy
///   sweep.json         (with a sweep) the body, its node range, start, translation, positions, penalty
///   <method>-eps<ε>/   each run's own outputs (steps.csv, newton.csv, VTU/PVD, summary.json)

#include <functional>
#include <string>
#include <vector>

#include "sinew/contact/contact_energy.hpp"
#include "sinew/core/types.hpp"
#include "sinew/scene/scene_config.hpp"

namespace sinew::app {

struct ConvergenceStudyOptions {
  std::string output_directory = "study";
  std::vector<double> penalties{0, 10, 100, 1000, 10000};  ///< ε (force / length^3); 0 = no contact
  std::vector<contact::ContactMethod> methods{contact::ContactMethod::Area, contact::ContactMethod::Point};
  /// A run converged when it solved every time step and its last equilibrium residual is at most
  /// `tolerance` times the largest equilibrium residual of the run (dimensionless), or when it
  /// started in equilibrium (no Newton iteration needed).
  double tolerance = 1e-6;
  double end_time = 0;  ///< > 0: overrides the scene's dynamics end_time (time)
  /// Force sweep: `sweep_body` (empty: none) translated rigidly from its rest place by
  /// sweep_from + s * sweep_translation, s = 0 .. 1 in `sweep_positions` positions (length);
  /// forces at `sweep_penalty`.
  std::string sweep_body;
  Vector3 sweep_from = Vector3::Zero();
  Vector3 sweep_translation = Vector3::Zero();
  int sweep_positions = 41;
  double sweep_penalty = 100;
  bool progress = true;  ///< a log line per run
  bool overwrite = false;  ///< empty an earlier sinew run's output directory first (see io::OutputDirectoryOptions)
  std::string command;     ///< recorded in the output directory's lock file
};

/// One solve of the study.
struct ConvergenceRun {
  contact::ContactMethod method = contact::ContactMethod::Area;
  double penalty = 0;
  bool solved = false;     ///< every time (or load) step converged
  bool converged = false;  ///< solved, and the equilibrium residual fell by `tolerance`
  int steps = 0;
  int newton_iterations = 0;
  int cuts = 0;
  double first_residual = 0;    ///< equilibrium residual at the start (force)
  double largest_residual = 0;  ///< largest equilibrium residual of the run (force)
  double final_residual = 0;    ///< equilibrium residual of the last iteration (force)
  double max_penetration = 0;   ///< largest depth inside another body at the end (length)
  double wall_seconds = 0;
  std::string message;
  std::string directory;  ///< the run's outputs, relative to the study directory
};

struct ConvergenceStudyReport {
  std::vector<ConvergenceRun> runs;
};

/// Requires a scene with a contact section. Throws InputError on a bad option (negative or
/// non-finite penalty, unknown sweep body, fewer than 2 sweep positions) before writing.
ConvergenceStudyReport run_convergence_study(const scene::SceneConfig& scene, const ConvergenceStudyOptions& options);

/// Table 1 as Markdown: one row per penalty, one column per method ("—" when a run failed).
std::string penetration_table_markdown(const ConvergenceStudyReport& report,
                                       const std::vector<contact::ContactMethod>& methods);

/// The scene name of `method` (contact::kContactMethodNames).
std::string contact_method_name(contact::ContactMethod method);

}  // namespace sinew::app
