#include "cli.hpp"

#include <algorithm>
#include <cmath>
#include <new>
#include <string>
#include <fstream>
#include <iostream>
#include <iterator>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <tbb/global_control.h>

#include "convergence_study.hpp"
#include "exit_codes.hpp"
#include "interrupt.hpp"
#include "parallel_run.hpp"
#include "run_scene.hpp"
#include "sinew/core/enum_names.hpp"
#include "sinew/core/error.hpp"
#include "sinew/core/log.hpp"
#include "sinew/io/atomic_file.hpp"
#include "sinew/io/output_directory.hpp"
#include "sinew/model/model.hpp"
#include "sinew/parallel/ranks.hpp"
#include "sinew/parallel/root_for_all.hpp"
#include "sinew/scene/element_size.hpp"
#include "sinew/scene/load_scene.hpp"
#include "sinew/scene/scene_schema.hpp"

namespace sinew::app {

namespace {

/// What the command line overrides in a scene: every generated mesh's element size (0:
/// unchanged; bodies read from files keep their meshes) and the largest estimated tetrahedron
/// count a body may have before meshing (0: the default).
struct SceneOverrides {
  double element_size = 0;
  double max_tets = 0;
  std::string data_directory;  ///< replaces the scene's data_dir when set
  std::string mesh_cache;      ///< directory of the mesh cache; empty = none (docs/mesh-cache.md)
};

scene::SceneConfig with_overrides(scene::SceneConfig config, const SceneOverrides& overrides) {
  if (overrides.element_size > 0) scene::set_element_size(config, overrides.element_size);
  if (!overrides.data_directory.empty()) config.data_directory = overrides.data_directory;
  if (overrides.max_tets > 0) config.limits.max_tets = overrides.max_tets;
  config.mesh_cache_directory = overrides.mesh_cache;
  return config;
}

/// A finite number > 0 (CLI::PositiveNumber lets NaN through and prints huge bounds in full).
const CLI::Validator kFinitePositive(
    [](std::string& text) -> std::string {
      double value = 0;
      std::size_t used = 0;
      try {
        value = std::stod(text, &used);
      } catch (const std::exception&) {
        return "not a number: " + text;
      }
      if (used != text.size()) return "not a number: " + text;
      if (!std::isfinite(value) || value <= 0) return "must be a finite number > 0, got " + text;
      return {};
    },
    "POSITIVE", "finite and > 0");

/// The scene file's bytes and the overrides: with the meshes, what identifies a run for
/// --resume (model::model_fingerprint).
std::string scene_identity(const std::string& scene_path, const SceneOverrides& overrides) {
  std::ifstream in(scene_path, std::ios::binary);
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return text + fmt::format("\n--element-size {:a} --max-tets {:a} --data-dir {}", overrides.element_size,
                            overrides.max_tets, overrides.data_directory);
}

/// The command line as one string, for the output directory's lock file.
std::string command_line(int argc, char** argv) {
  std::string text = "sinew";
  for (int i = 1; i < argc; ++i) text += std::string(" ") + argv[i];
  return text;
}

int code(ExitCode exit_code) { return static_cast<int>(exit_code); }

int run_commands(int argc, char** argv);

}  // namespace

int run_cli(int argc, char** argv) {
  // Every failure ends here as a message and a documented exit code, never as a signal. On
  // several MPI ranks a failure of one rank alone ends them all (parallel_run.hpp).
  auto fail = [](ExitCode exit_code, const std::string& message, bool every_rank_saw_it) {
    log_failure(message, every_rank_saw_it);
    end_ranks_after_failure(code(exit_code), every_rank_saw_it);
    return code(exit_code);
  };
  try {
    start_ranks();
    return run_commands(argc, argv);
  } catch (const InputError& e) {  // the same on every rank (or passed on by on_root_for_all)
    return fail(ExitCode::InputRejected, e.what(), true);
  } catch (const RunInterrupted& e) {  // every rank stops at the same point (run_scene.cpp)
    return fail(ExitCode::Interrupted, e.what(), true);
  } catch (const OutputError& e) {
    return fail(ExitCode::OutputFailed, e.what(), false);
  } catch (const OutOfMemoryError& e) {
    return fail(ExitCode::OutOfMemory, e.what(), false);
  } catch (const std::bad_alloc&) {
    return fail(ExitCode::OutOfMemory,
                "out of memory (an allocation failed); try a coarser mesh or a machine with more memory", false);
  } catch (const Error& e) {
    return fail(ExitCode::InputRejected, e.what(), false);
  } catch (const std::exception& e) {
    return fail(ExitCode::InternalError, fmt::format("internal error: {} (please report it with the scene)", e.what()),
                false);
  } catch (...) {
    return fail(ExitCode::InternalError, "internal error: an unknown exception (please report it with the scene)",
                false);
  }
}

namespace {

int run_commands(int argc, char** argv) {
  CLI::App cli{"sinew: implicit finite elements for elastic solids in contact"};
  cli.footer(exit_codes_help());
  cli.require_subcommand(0, 1);  // checked after parsing, so an unknown option is named first
  cli.fallthrough();  // global options (-q, -j) may also follow the subcommand
  int threads = 0;
  bool quiet = false;
  cli.add_option("-j,--threads", threads,
                 "worker threads (default: all cores; under mpirun, the cores shared among the ranks on the node)")
      ->check(CLI::Range(0, 4096));
  cli.add_flag("-q,--quiet", quiet, "only warnings and errors");

  auto* run = cli.add_subcommand("run", "solve a scene and write VTU/PVD, CSV logs and a summary");
  std::string scene_path;
  RunOptions run_options;
  bool no_progress = false;
  run->add_option("scene", scene_path, "scene file (JSON)")->required();
  run->add_option("-o,--output", run_options.output_directory, "output directory")->capture_default_str();
  run->add_flag("--no-progress", no_progress, "never draw the progress bar");
  run->add_flag("--overwrite", run_options.overwrite,
                "replace the results of an earlier sinew run in the output directory (a directory sinew did not "
                "write is never emptied)");
  SceneOverrides overrides;
  const std::string element_size_help =
      "override the element_size of every generated or surface mesh (length): the same scene coarser or finer (size "
      "zones keep their ratio to it)";
  const std::string data_dir_help = "directory of the scene's surface files (replaces its \"data_dir\")";
  const std::string max_tets_help = fmt::format(
      "refuse a generated body whose estimated tetrahedron count exceeds this before meshing (default {:g})",
      scene::ResourceLimits{}.max_tets);
  run->add_option("--element-size", overrides.element_size, element_size_help)->check(kFinitePositive);
  run->add_option("--max-tets", overrides.max_tets, max_tets_help)->check(kFinitePositive);
  run->add_option("--data-dir", overrides.data_directory, data_dir_help);
  const std::string mesh_cache_help =
      "directory of meshes generated before: a body whose mesh section, element size, surface files and sinew "
      "executable match an entry is read from it instead of meshed again; new meshes are added (docs/mesh-cache.md)";
  run->add_option("--mesh-cache", overrides.mesh_cache, mesh_cache_help);
  run->add_flag("--resume", run_options.resume,
                "continue the run in the output directory from its checkpoint (same scene and options; after an "
                "interrupt, a kill or a crash)");

  auto* validate = cli.add_subcommand("validate", "check a scene (schema, meshes, constraints) without solving");
  std::string validate_path;
  validate->add_option("scene", validate_path, "scene file (JSON)")->required();
  validate->add_option("--element-size", overrides.element_size, element_size_help)->check(kFinitePositive);
  validate->add_option("--max-tets", overrides.max_tets, max_tets_help)->check(kFinitePositive);
  validate->add_option("--data-dir", overrides.data_directory, data_dir_help);
  validate->add_option("--mesh-cache", overrides.mesh_cache, mesh_cache_help);

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
  std::vector<std::string> study_methods = names_of<contact::ContactMethod>();
  std::vector<double> sweep_translation, sweep_from;
  convergence->add_option("scene", study_path, "scene file (JSON) with a contact section")->required();
  convergence->add_option("-o,--output", study_options.output_directory, "output directory")->capture_default_str();
  convergence->add_flag("--overwrite", study_options.overwrite,
                        "replace the results of an earlier sinew study in the output directory");
  convergence->add_option("--penalties", study_options.penalties, "penalties to run (0: no contact)")
      ->delimiter(',')
      ->capture_default_str();
  convergence->add_option("--methods", study_methods, "contact methods to run")
      ->delimiter(',')
      ->check(CLI::IsMember(names_of<contact::ContactMethod>()))
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
    // --help prints and exits 0; every mistake prints its message and exits 1.
    return cli.exit(e) == 0 ? code(ExitCode::Success) : code(ExitCode::InputRejected);
  }
  if (cli.get_subcommands().empty()) {
    std::string given = argc > 1 ? std::string(" (got \"") + argv[1] + "\")" : std::string();
    return cli.exit(CLI::RequiredError("a subcommand is required: run, validate, schema or study" + given)) == 0
               ? code(ExitCode::Success)
               : code(ExitCode::InputRejected);
  }
  if (quiet && parallel::is_root()) logger().set_level(spdlog::level::warn);  // the other ranks stay silent
  std::unique_ptr<tbb::global_control> thread_limit;
  if (threads == 0) threads = threads_per_rank();  // 0 (all cores) on one rank
  if (threads > 0)
    thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);

  {
    if (*schema) {
      const std::string text = markdown ? scene::scene_reference_markdown() : scene::scene_json_schema().dump(2) + "\n";
      if (schema_output.empty())
        std::cout << text;
      else
        io::write_file_atomically(schema_output, text);
      return code(ExitCode::Success);
    }
    if (*validate) {
      const auto config = with_overrides(scene::load_scene_file(validate_path), overrides);
      // Exactly the model a run builds: meshes, constraints, contact (depths, penalties) and
      // dynamics (masses, time steps) are checked.
      const model::Model model = model::build_model(config);
      const fem::Problem& problem = *model.problem;
      std::string extras;
      if (model.contact) extras += fmt::format(", contact between {} bodies", model.contact->num_bodies());
      if (model.is_dynamic()) extras += ", dynamics";
      std::cout << fmt::format("{}: valid ({} bodies, {} nodes, {} tets, {} unknowns{})\n", validate_path,
                               config.bodies.size(), problem.mesh.num_nodes(), problem.mesh.num_tets(),
                               model.dofs->num_dofs(), extras);
      return code(ExitCode::Success);
    }
    if (*convergence) {
      study_options.methods.clear();
      for (const auto& m : study_methods) {
        // --methods is checked against the same name table (IsMember above): every name parses.
        study_options.methods.push_back(parse_name<contact::ContactMethod>(m).value());
      }
      if (sweep_from.size() == 3) study_options.sweep_from = Vector3(sweep_from[0], sweep_from[1], sweep_from[2]);
      if (sweep_translation.size() == 3)
        study_options.sweep_translation = Vector3(sweep_translation[0], sweep_translation[1], sweep_translation[2]);
      if (!study_options.sweep_body.empty() && sweep_translation.size() != 3)
        throw InputError("study convergence: --sweep-body needs --sweep-translation X Y Z");
      study_options.progress = !quiet;
      study_options.command = command_line(argc, argv);
      io::check_output_directory(study_options.output_directory, {.overwrite = study_options.overwrite});
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
      return code(ExitCode::Success);
    }
    run_options.progress_bar = !no_progress && parallel::is_root();
    run_options.log_steps = !quiet;
    run_options.command = command_line(argc, argv);
    // The output directory is checked before any work (nothing is written until the scene has
    // passed every check).
    parallel::on_root_for_all([&] {
      io::check_output_directory(run_options.output_directory,
                                 {.overwrite = run_options.overwrite, .resume = run_options.resume});
    });
    const auto config = with_overrides(scene::load_scene_file(scene_path), overrides);
    run_options.scene_identity = scene_identity(scene_path, overrides);
    run_options.resume_command = "sinew";
    for (int i = 1; i < argc; ++i)
      if (std::string(argv[i]) != "--overwrite") run_options.resume_command += std::string(" ") + argv[i];
    if (!run_options.resume) run_options.resume_command += " --resume";
    const RunReport report = run_scene(config, run_options);
    if (!report.success) {
      logger().error("{}", report.message);
      logger().error("outputs so far, and the last converged state (last_converged.vtu), are in {}",
                     run_options.output_directory);
      return code(ExitCode::SolveStopped);
    }
    logger().info("{}; results in {}", report.message, run_options.output_directory);
    return code(ExitCode::Success);
  }
}

}  // namespace

}  // namespace sinew::app
