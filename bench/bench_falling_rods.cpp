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

#include <string>
#include <vector>

#include "bench_run_support.hpp"
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
  for (auto _ : state) {
    const app::RunReport report = bench::run_once(state, config, "falling_rods");
    const auto& r = report.result;
    state.counters["simulated_s"] = r.t;
    state.counters["steps"] = r.steps;
    state.counters["newton_its"] = r.newton_iterations;
    state.counters["cuts"] = r.cuts;
    bench::set_phase_counters(state, report, r.times);
  }
}

BENCHMARK_CAPTURE(BM_FallingRods, reduced, true)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);
BENCHMARK_CAPTURE(BM_FallingRods, full, false)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
