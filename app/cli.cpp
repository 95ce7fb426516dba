#include "cli.hpp"

#include <algorithm>
#include <iostream>

#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include "convergence_study.hpp"
#include "run_scene.hpp"
#include "static_model.hpp"
#include "sinew/scene/build_problem.hpp"
#include "sinew/core/error.hpp"
#include "sinew/core/log.hpp"
#include "sinew/io/atomic_file.hpp"
#include "sinew/scene/load_scene.hpp"
#include "sinew/scene/scene_schema.hpp"

namespace sinew::app {

namespace {

/// The scene with every generated mesh's element size set to `size` (0: unchanged). Bodies
/// read from files keep their meshes.
scene::SceneConfig with_element_size(scene::SceneConfig config, double size) {
  if (size > 0)
    for (auto& body : config.bodies)
      if (body.mesh.file.empty()) body.mesh.generate.element_size = size;
  return config;
}

}  // namespace

int run_cli(int argc, char** argv) {
  CLI::App cli{"sinew: implicit finite elements for elastic solids in contact"};
  cli.require_subcommand(1);
  cli.fallthrough();  // global options (-q, -j) may also follow the subcommand
  int threads = 0;
  bool quiet = false;
  cli.add_option("-j,--threads", threads, "worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  cli.add_flag("-q,--quiet", quiet, "only warnings and errors");

  auto* run = cli.add_subcommand("run", "solve a scene and write VTU/PVD, CSV logs and a summary");
  std::string scene_path;
  RunOptions run_options;
  bool no_progress = false;
  run->add_option("scene", scene_path, "scene file (JSON)")->required();
  run->add_option("-o,--output", run_options.output_directory, "output directory")->capture_default_str();
  run->add_flag("--no-progress", no_progress, "never draw the progress bar");
  double element_size = 0;
  const std::string element_size_help =
      "override the element_size of every generated mesh (length): the same scene coarser or finer";
  run->add_option("--element-size", element_size, element_size_help)->check(CLI::PositiveNumber);

  auto* validate = cli.add_subcommand("validate", "check a scene (schema, meshes, constraints) without solving");
  std::string validate_path;
  validate->add_option("scene", validate_path, "scene file (JSON)")->required();
  validate->add_option("--element-size", element_size, element_size_help)->check(CLI::PositiveNumber);

  auto* schema = cli.add_subcommand("schema", "print the scene format");
  bool markdown = false, json = false;
  std::string schema_output;
  auto* format = schema->add_option_group("format");
  format->add_flag("--markdown", markdown, "the Markdown reference (docs/scene-reference.md)");
  format->add_flag("--json", json, "a JSON Schema (draft-07) for editors");
  format->require_option(1);
  schema->add_option("-o,--output", schema_output, "write to this file instead of standard output");

  auto* study = cli.add_subcommand("study", "studies that solve a scene many times");
  study->require_subcommand(1);
  auto* convergence = study->add_subcommand(
      "convergence", "area integration against point collocation over penalties (dissertation 6.5): residual "
                     "histories, converged or not, penetration table, force sweep");
  std::string study_path;
  ConvergenceStudyOptions study_options;
  std::vector<std::string> study_methods{"area", "point"};
  std::vector<double> sweep_translation, sweep_from;
  convergence->add_option("scene", study_path, "scene file (JSON) with a contact section")->required();
  convergence->add_option("-o,--output", study_options.output_directory, "output directory")->capture_default_str();
  convergence->add_option("--penalties", study_options.penalties, "penalties to run (0: no contact)")
      ->delimiter(',')
      ->capture_default_str();
  convergence->add_option("--methods", study_methods, "contact methods to run")
      ->delimiter(',')
      ->check(CLI::IsMember({"area", "point"}))
      ->capture_default_str();
  convergence->add_option("--tolerance", study_options.tolerance,
                          "converged: the last equilibrium residual is at most this fraction of the run's largest")
      ->capture_default_str();
  convergence->add_option("--end-time", study_options.end_time, "override the scene's dynamics end_time");
  convergence->add_option("--sweep-body", study_options.sweep_body,
                          "sweep this body rigidly through the others and record its contact forces");
  convergence->add_option("--sweep-translation", sweep_translation, "the sweep's full translation (x y z)")
      ->expected(3);
  convergence->add_option("--sweep-from", sweep_from, "the sweep's first offset from the rest place (x y z)")
      ->expected(3);
  convergence->add_option("--sweep-positions", study_options.sweep_positions, "positions of the sweep")
      ->capture_default_str();
  convergence->add_option("--sweep-penalty", study_options.sweep_penalty, "penalty of the sweep's forces")
      ->capture_default_str();

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return cli.exit(e);
  }
  if (quiet) logger().set_level(spdlog::level::warn);
  std::unique_ptr<tbb::global_control> thread_limit;
  if (threads > 0)
    thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);

  try {
    if (*schema) {
      const std::string text = markdown ? scene::scene_reference_markdown() : scene::scene_json_schema().dump(2) + "\n";
      if (schema_output.empty())
        std::cout << text;
      else
        io::write_file_atomically(schema_output, text);
      return 0;
    }
    if (*validate) {
      const auto config = with_element_size(scene::load_scene_file(validate_path), element_size);
      const fem::Problem problem = scene::build_problem(config);
      // The same model a run builds: contact (depths, penalties) and dynamics (masses, time
      // steps) are checked too.
      const std::optional<ContactInput> contact = make_contact_input(config, problem);
      const auto model = make_static_model(problem, config.solver, contact ? &*contact : nullptr, &config.dynamics);
      std::string extras;
      if (model.contact) extras += fmt::format(", contact between {} bodies", model.contact->num_bodies());
      if (model.mass) extras += ", dynamics";
      std::cout << fmt::format("{}: valid ({} bodies, {} nodes, {} tets, {} unknowns{})\n", validate_path,
                               config.bodies.size(), problem.mesh.num_nodes(), problem.mesh.num_tets(),
                               model.dofs->num_dofs(), extras);
      return 0;
    }
    if (*convergence) {
      study_options.methods.clear();
      for (const auto& m : study_methods)
        study_options.methods.push_back(m == "point" ? contact::ContactMethod::Point : contact::ContactMethod::Area);
      if (sweep_from.size() == 3) study_options.sweep_from = Vector3(sweep_from[0], sweep_from[1], sweep_from[2]);
      if (sweep_translation.size() == 3)
        study_options.sweep_translation = Vector3(sweep_translation[0], sweep_translation[1], sweep_translation[2]);
      if (!study_options.sweep_body.empty() && sweep_translation.size() != 3)
        throw InputError("study convergence: --sweep-body needs --sweep-translation X Y Z");
      study_options.progress = !quiet;
      const auto config = scene::load_scene_file(study_path);
      const ConvergenceStudyReport report = run_convergence_study(config, study_options);
      const bool all_solved = std::all_of(report.runs.begin(), report.runs.end(),
                                          [](const ConvergenceRun& r) { return r.solved; });
      std::cout << penetration_table_markdown(report, study_options.methods);
      logger().info("study written to {} (residuals.csv, runs.csv, penetration.md{}); plots: /usr/bin/python3 "
                    "scripts/plot_convergence_study.py {}",
                    study_options.output_directory, study_options.sweep_body.empty() ? "" : ", sweep_*.csv",
                    study_options.output_directory);
      if (!all_solved) logger().warn("some runs stopped before their end (see runs.csv); this is a result, not an error");
      return 0;
    }
    run_options.progress_bar = !no_progress;
    run_options.log_steps = !quiet;
    const auto config = with_element_size(scene::load_scene_file(scene_path), element_size);
    const RunReport report = run_scene(config, run_options);
    if (!report.success) {
      logger().error("{}", report.message);
      logger().error("outputs so far, and the last converged state (last_converged.vtu), are in {}",
                     run_options.output_directory);
      return 2;
    }
    logger().info("{}; results in {}", report.message, run_options.output_directory);
    return 0;
  } catch (const InputError& e) {
    logger().error("{}", e.what());
    return 1;
  } catch (const Error& e) {
    logger().error("{}", e.what());
    return 1;
  }
}

}  // namespace sinew::app
