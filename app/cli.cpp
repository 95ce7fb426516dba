#include "cli.hpp"

#include <iostream>

#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include "run_scene.hpp"
#include "static_model.hpp"
#include "sinew/scene/build_problem.hpp"
#include "sinew/core/error.hpp"
#include "sinew/core/log.hpp"
#include "sinew/io/atomic_file.hpp"
#include "sinew/scene/load_scene.hpp"
#include "sinew/scene/scene_schema.hpp"

namespace sinew::app {

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

  auto* validate = cli.add_subcommand("validate", "check a scene (schema, meshes, constraints) without solving");
  std::string validate_path;
  validate->add_option("scene", validate_path, "scene file (JSON)")->required();

  auto* schema = cli.add_subcommand("schema", "print the scene format");
  bool markdown = false, json = false;
  std::string schema_output;
  auto* format = schema->add_option_group("format");
  format->add_flag("--markdown", markdown, "the Markdown reference (docs/scene-reference.md)");
  format->add_flag("--json", json, "a JSON Schema (draft-07) for editors");
  format->require_option(1);
  schema->add_option("-o,--output", schema_output, "write to this file instead of standard output");

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
      const auto config = scene::load_scene_file(validate_path);
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
    run_options.progress_bar = !no_progress;
    run_options.log_steps = !quiet;
    const auto config = scene::load_scene_file(scene_path);
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
