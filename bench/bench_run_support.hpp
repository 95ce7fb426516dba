#pragma once
/// @file bench_run_support.hpp
/// Shared by the benchmarks that run an example scene through the product's own run path
/// (app::run_scene): one run into a temporary directory, and the per-phase counters.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "run_scene.hpp"
#include "sinew/core/log.hpp"

namespace sinew::bench {

/// Runs `config` once with logging at warnings and no progress bar, into a temporary directory
/// named after `tag` that is removed afterwards; records the wall time as the iteration time.
inline app::RunReport run_once(benchmark::State& state, const scene::SceneConfig& config, const std::string& tag) {
  const std::filesystem::path output =
      std::filesystem::temp_directory_path() / ("sinew_bench_" + tag + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(output);
  logger().set_level(spdlog::level::warn);
  app::RunOptions options;
  options.output_directory = output.string();
  options.progress_bar = false;
  options.log_steps = false;
  const app::RunReport report = app::run_scene(config, options);
  std::filesystem::remove_all(output);
  state.SetIterationTime(report.wall_seconds);
  if (!report.success) state.SkipWithError(report.message.c_str());
  return report;
}

/// wall_s, solve_s and the share of each phase of `times` in the report's wall time, in %.
inline void set_phase_counters(benchmark::State& state, const app::RunReport& report, const solver::PhaseTimes& times) {
  const double wall = std::max(report.wall_seconds, 1e-12);
  state.counters["wall_s"] = report.wall_seconds;
  state.counters["solve_s"] = report.wall_seconds - report.setup_seconds;
  state.counters["setup_%"] = 100 * report.setup_seconds / wall;
  state.counters["forces_stiffness_%"] = 100 * times.forces_and_stiffness / wall;
  state.counters["collision_%"] = 100 * times.collision / wall;
  state.counters["linear_solve_%"] = 100 * times.linear_solve / wall;
  state.counters["line_search_%"] = 100 * times.line_search / wall;
  state.counters["other_%"] = 100 * std::max(0.0, wall - report.setup_seconds - times.total()) / wall;
}

}  // namespace sinew::bench
