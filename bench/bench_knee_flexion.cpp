/// Benchmark (issue 6): the knee flexion (dissertation section 7, paper section 6;
/// examples/knee-flexion.json) through the product's own run path: meshing, material depth,
/// the 150-degree flexion in 50 increments with contact, CSV output into a temporary directory
/// (no VTU files). The seed took 376 minutes on its 2001 machine for its 10k-node / 40k-tet
/// mesh, 63 % of it in forces and stiffness, 22 % in collision and 15 % in the linear solve.
/// Prints wall time, increments, Newton iterations, cuts and the per-phase split:
///   setup (meshing, depth) / forces and stiffness / collision / linear solve / line search / other.
///
/// Variants by element size: `h16` (4.5k nodes, the main job's default), `h12` and `full` (the
/// scene as written, 9 mm: 9.1k nodes / 41k tets). `hull_*`: the same sizes on
/// examples/knee-flexion-hull.json, the leg with the seed's shrink-wrap hull and voids in the thigh
/// (the main job until 2026-12-03, the reference of the speed figures measured before). `BM_VhKneeFlexion/full` runs
/// examples/vh-knee-flexion.json (the Visible Human surfaces, meshed by sinew, issue 14) as
/// written; it reports an error when the data is not beside the repository. Select with
/// --benchmark_filter. Timings are measured here, never asserted in tests.

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "bench_run_support.hpp"
#include "sinew/scene/load_scene.hpp"

using namespace sinew;

namespace {

/// The run's counts and per-phase split as benchmark counters.
void record(benchmark::State& state, const app::RunReport& report) {
  const auto& r = report.result;
  state.counters["increments"] = r.segments_completed;
  state.counters["steps"] = r.steps;
  state.counters["newton_its"] = r.newton_iterations;
  state.counters["cuts"] = r.cuts;
  state.counters["factorizations"] = r.linear.factorizations;
  state.counters["linear_its"] = r.linear.linear_iterations;
  state.counters["undone_lagged"] = r.linear.undone_lagged_steps;
  bench::set_phase_counters(state, report, r.times);
}

void BM_KneeFlexion(benchmark::State& state, const char* scene_name, double element_size, int lagged_iterations) {
  scene::SceneConfig config =
      scene::load_scene_file(std::string(SINEW_SOURCE_DIR) + "/examples/" + scene_name + ".json");
  if (element_size > 0)
    for (auto& body : config.bodies) body.mesh.generate.element_size = element_size;
  config.solver.linear.lagged_iterations = lagged_iterations;
  config.output.vtu = false;
  for (auto _ : state) {
    record(state, bench::run_once(state, config, "knee"));
  }
}

void BM_VhKneeFlexion(benchmark::State& state) {
  scene::SceneConfig config = scene::load_scene_file(std::string(SINEW_SOURCE_DIR) + "/examples/vh-knee-flexion.json");
  if (!std::filesystem::exists(std::filesystem::path(config.data_directory) / "VH_M_Knee_R.glb")) {
    state.SkipWithError(("the VH knee data is not in " + config.data_directory).c_str());
    return;
  }
  config.output.vtu = false;
  for (auto _ : state) {
    record(state, bench::run_once(state, config, "vh-knee"));
  }
}

// Each size with and without lagged factorizations, one after the other (a shared machine:
// compare within a run). Filter with --benchmark_filter.
#define SINEW_KNEE_BENCHMARK(label, scene, size, lagged)                   \
  BENCHMARK_CAPTURE(BM_KneeFlexion, label, scene, size, lagged)            \
      ->Iterations(1)                                                      \
      ->UseManualTime()                                                    \
      ->Unit(benchmark::kSecond)
SINEW_KNEE_BENCHMARK(h16, "knee-flexion", 16.0, 0);
SINEW_KNEE_BENCHMARK(h16_lagged10, "knee-flexion", 16.0, 10);
SINEW_KNEE_BENCHMARK(h16_lagged20, "knee-flexion", 16.0, 20);
SINEW_KNEE_BENCHMARK(h12, "knee-flexion", 12.0, 0);
SINEW_KNEE_BENCHMARK(full, "knee-flexion", 0.0, 0);
SINEW_KNEE_BENCHMARK(full_lagged20, "knee-flexion", 0.0, 20);
SINEW_KNEE_BENCHMARK(hull_h16, "knee-flexion-hull", 16.0, 0);
SINEW_KNEE_BENCHMARK(hull_full, "knee-flexion-hull", 0.0, 0);
BENCHMARK(BM_VhKneeFlexion)->Name("BM_VhKneeFlexion/full")->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
