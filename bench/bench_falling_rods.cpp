/// Benchmark (issue 4): the falling-rods scene (dissertation §8.2, Fig. 51; examples/falling-rods.json)
/// through the product's own run path (mesh generation, contact setup, implicit Euler with
/// contact, CSV and VTU output into a temporary directory). The seed took about 3 hours on its
/// 2001 machine. Prints wall time, steps, Newton iterations and the per-phase split:
///   forces and stiffness / collision (broad and narrow phase) / linear solve / line search / other.
///
/// Variants: `full` (7 x 5 rods, the scene as written, several minutes) and `reduced` (the test's
/// 2 x 3 rods for 0.5 s). Select with --benchmark_filter=full or =reduced. Timings are
/// measured here, never asserted in tests.

#include <benchmark/benchmark.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "run_scene.hpp"
#include "sinew/core/log.hpp"
#include "sinew/scene/load_scene.hpp"

using namespace sinew;

namespace {

scene::SceneConfig falling_rods(bool reduced) {
  scene::SceneConfig config =
      scene::load_scene_file(std::string(SINEW_SOURCE_DIR) + "/examples/falling-rods.json");
  if (reduced) {
    auto& rods = config.bodies.at(0).mesh.parts.at(0).shape.children;
    std::vector<mesh::Shape> kept;
    for (int row = 0; row < 2; ++row)
      for (int column = 2; column < 5; ++column) kept.push_back(rods.at(static_cast<std::size_t>(7 * row + column)));
    rods = kept;
    config.dynamics.options.end_time = 0.5;
    config.dynamics.options.output_interval = 0.1;
  }
  return config;
}

void BM_FallingRods(benchmark::State& state, bool reduced) {
  const scene::SceneConfig config = falling_rods(reduced);
  const std::filesystem::path output =
      std::filesystem::temp_directory_path() / ("sinew_bench_falling_rods_" + std::to_string(::getpid()));
  logger().set_level(spdlog::level::warn);
  for (auto _ : state) {
    std::filesystem::remove_all(output);
    app::RunOptions options;
    options.output_directory = output.string();
    options.progress_bar = false;
    options.log_steps = false;
    const app::RunReport report = app::run_scene(config, options);
    state.SetIterationTime(report.wall_seconds);
    if (!report.success) state.SkipWithError(report.message.c_str());
    const auto& r = report.dynamic_result;
    const auto& t = r.times;
    const double wall = std::max(report.wall_seconds, 1e-12);
    state.counters["simulated_s"] = r.time;
    state.counters["steps"] = r.steps;
    state.counters["newton_its"] = r.newton_iterations;
    state.counters["cuts"] = r.cuts;
    state.counters["wall_s"] = report.wall_seconds;
    state.counters["forces_stiffness_%"] = 100 * t.forces_and_stiffness / wall;
    state.counters["collision_%"] = 100 * t.collision / wall;
    state.counters["linear_solve_%"] = 100 * t.linear_solve / wall;
    state.counters["line_search_%"] = 100 * t.line_search / wall;
    state.counters["other_%"] = 100 * std::max(0.0, wall - t.total()) / wall;
  }
  std::filesystem::remove_all(output);
}

BENCHMARK_CAPTURE(BM_FallingRods, reduced, true)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_FallingRods, full, false)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
