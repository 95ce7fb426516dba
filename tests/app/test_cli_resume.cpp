/// @file test_cli_resume.cpp
/// Checkpoints, --resume and the graceful interrupt (docs/checkpoints.md), through the real
/// executable: a run killed with SIGKILL at random moments and resumed each time ends with the
/// CSV logs, the series and the VTU files of an uninterrupted run; SIGINT and SIGTERM stop a run
/// with exit code 6, a checkpoint and a message that says how to go on; a checkpoint of another
/// scene, a damaged one or none is refused with a clear message before anything is written.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "app/app_test_support.hpp"

namespace sinew::app_test {
namespace {

using ::testing::HasSubstr;

#ifdef SINEW_SANITIZER_BUILD
constexpr int kKills = 3;  // the instrumented build is several times slower
#else
constexpr int kKills = 10;
#endif

/// Every numeric cell of two CSV files agrees to `relative` (or 1e-10 absolute; text cells
/// exactly); same rows.
void expect_same_csv(const fs::path& expected, const fs::path& actual, double relative) {
  SCOPED_TRACE(actual.string());
  const auto a = read_csv_cells(expected), b = read_csv_cells(actual);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a.front(), b.front());
  for (std::size_t i = 1; i < a.size(); ++i) {
    ASSERT_EQ(a[i].size(), b[i].size()) << "row " << i;
    for (std::size_t j = 0; j < a[i].size(); ++j) {
      char* end_a = nullptr;
      char* end_b = nullptr;
      const double x = std::strtod(a[i][j].c_str(), &end_a), y = std::strtod(b[i][j].c_str(), &end_b);
      if (*end_a != '\0' || *end_b != '\0') {
        EXPECT_EQ(a[i][j], b[i][j]) << "row " << i << ", column " << a.front()[j];
        continue;
      }
      // Converged residuals (~1e-13) are round-off themselves: an absolute floor of 1e-10.
      EXPECT_LE(std::abs(x - y), relative * std::max(std::abs(x), std::abs(y)) + 1e-10)
          << "row " << i << ", column " << a.front()[j] << ": " << a[i][j] << " vs " << b[i][j];
    }
  }
}

/// The numbers of a VTU file (its ASCII and base64 data differ only when the values do), compared
/// by the share of equal bytes: a resumed run rewrites the same files from the same state.
void expect_same_vtu_set(const fs::path& expected, const fs::path& actual) {
  std::vector<std::string> a, b;
  for (const auto& e : fs::directory_iterator(expected / "vtu")) a.push_back(e.path().filename().string());
  for (const auto& e : fs::directory_iterator(actual / "vtu")) b.push_back(e.path().filename().string());
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b);
  for (const auto& name : a) {
    const std::string x = read_text(expected / "vtu" / name), y = read_text(actual / "vtu" / name);
    EXPECT_EQ(x.size(), y.size()) << name;  // same fields and sizes; values are checked through the CSV
  }
  EXPECT_EQ(read_text(expected / "sinew.pvd"), read_text(actual / "sinew.pvd"));
}

/// The stacked blocks with the adaptive penalty (its penalties change during the run and must
/// come back on resume) in 24 increments: about 3 s.
json adaptive_blocks_scene() {
  json scene = json::parse(read_text(kSource / "examples" / "stacked-blocks.json"));
  scene["contact"]["penalty"] = 0.0636;
  scene["contact"]["enforcement"] = {{"method", "adaptive-penalty"}, {"penetration_tolerance", 0.002}};
  scene["solver"]["increments"] = 24;
  return scene;
}

class Resume : public ::testing::Test {
 protected:
  TempDir directory;
  fs::path scene_path = directory / "scene.json";
  fs::path reference = directory / "reference";
  fs::path output = directory / "out";

  std::vector<std::string> arguments(const fs::path& out, std::vector<std::string> extra = {}) const {
    std::vector<std::string> a{"run", scene_path.string(), "-o", out.string(), "--no-progress", "-j", "2"};
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  }
};

TEST_F(Resume, ARunKilledAtRandomMomentsAndResumedEachTimeEndsAsAnUninterruptedOne) {
  write_text(scene_path, adaptive_blocks_scene().dump(2));
  const auto start = std::chrono::steady_clock::now();
  const CommandResult full = run_sinew(arguments(reference), directory);
  const auto full_time = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start);
  ASSERT_EQ(full.exit_code, 0) << full.err;
  EXPECT_THAT(read_text(reference / "steps.csv"), HasSubstr("contact.lower.upper.penalty"));

  // Each attempt meshes first (setup), then steps: kill it within its first fifth of the
  // stepping on average, so that most of the attempts are killed and every one makes progress.
  const json full_summary = json::parse(read_text(reference / "summary.json"));
  const auto setup_ms = static_cast<long long>(1000 * full_summary.at("seconds").at("setup").get<double>());
  const long long stepping_ms = std::max<long long>(50, full_time.count() - setup_ms);
  std::mt19937 random(20261130);
  std::uniform_int_distribution<long long> moment(setup_ms / 2, setup_ms + 2 * stepping_ms / kKills);
  std::uniform_int_distribution<long long> after_checkpoint(0, 2 * stepping_ms / kKills);
  int resumed = 0, killed = 0;
  for (int k = 0; k < kKills; ++k) {
    const bool has_checkpoint = fs::exists(output / "checkpoint.cbor");
    std::vector<std::string> extra;
    if (has_checkpoint)
      extra.push_back("--resume");
    else if (fs::exists(output))
      extra.push_back("--overwrite");  // killed before its first checkpoint: start again
    resumed += has_checkpoint ? 1 : 0;
    // The first attempt is killed at a moment counted from its first checkpoint, so that the
    // others resume however much slower or faster this machine is now than in the reference run;
    // the others at a moment counted from their start (meshing, reading the checkpoint, stepping).
    const SignalPlan plan =
        k == 0 ? SignalPlan{.signal = SIGKILL,
                            .ready = output / "checkpoint.cbor",
                            .delay = std::chrono::milliseconds(after_checkpoint(random))}
               : SignalPlan{.signal = SIGKILL, .delay = std::chrono::milliseconds(moment(random))};
    const int status = run_and_signal(arguments(output, extra), directory, plan).status;
    if (WIFSIGNALED(status)) {
      ++killed;
    } else {
      ASSERT_TRUE(WIFEXITED(status));
      ASSERT_EQ(WEXITSTATUS(status), 0) << "attempt " << k;
    }
  }
  std::vector<std::string> last;
  if (fs::exists(output / "checkpoint.cbor"))
    last.push_back("--resume");
  else if (fs::exists(output))
    last.push_back("--overwrite");
  const CommandResult end = run_sinew(arguments(output, last), directory);
  ASSERT_EQ(end.exit_code, 0) << end.err;
  EXPECT_GE(killed, kKills / 2);
  EXPECT_GE(resumed, 1);
  std::printf("[   info   ] %d of %d attempts killed, %d resumed; uninterrupted run %lld ms\n", killed, kKills,
              resumed, static_cast<long long>(full_time.count()));

  // Equal to round-off: a resumed run's sparse pattern and ordering start anew, and Newton's
  // iterates far from the solution amplify that (newton.csv), converged values do not.
  expect_same_csv(reference / "steps.csv", output / "steps.csv", 1e-9);
  expect_same_csv(reference / "newton.csv", output / "newton.csv", 1e-4);
  expect_same_vtu_set(reference, output);
  const json a = json::parse(read_text(reference / "summary.json")), b = json::parse(read_text(output / "summary.json"));
  for (const char* key : {"steps", "newton_iterations", "step_cuts", "increments_completed", "status"})
    EXPECT_EQ(a.at(key), b.at(key)) << key;
}

TEST_F(Resume, SigintStopsADynamicRunWithItsOwnExitCodeAndACheckpointThatResumesExactly) {
  // Implicit Euler with friction: velocities and the friction lag come back.
  write_text(scene_path, read_text(kSource / "examples" / "block-on-incline.json"));
  const CommandResult full = run_sinew(arguments(reference), directory);
  ASSERT_EQ(full.exit_code, 0) << full.err;

  // Interrupted while it steps: once its first checkpoint is on disk (a few tries cover a machine
  // so slow or so fast that the signal misses the stepping).
  int status = 0;
  for (int delay_ms : {30, 10, 60, 0}) {
    fs::remove_all(output);
    status = run_and_signal(arguments(output), directory,
                            SignalPlan{.signal = SIGINT, .ready = output / "checkpoint.cbor",
                                       .delay = std::chrono::milliseconds(delay_ms)})
                 .status;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 6 && fs::exists(output / "checkpoint.cbor")) break;
  }
  ASSERT_TRUE(WIFEXITED(status)) << "ended by a signal";
  ASSERT_EQ(WEXITSTATUS(status), 6);
  const json summary = json::parse(read_text(output / "summary.json"));
  EXPECT_EQ(summary.at("status"), "interrupted");
  EXPECT_THAT(summary.at("message").get<std::string>(), HasSubstr("interrupted by SIGINT at t = "));
  EXPECT_THAT(summary.at("message").get<std::string>(), HasSubstr("--resume"));
  // The phase times up to the last accepted step (a checkpoint is on disk: Newton has worked).
  EXPECT_GT(summary.at("seconds").at("forces_and_stiffness").get<double>(), 0);
  EXPECT_GT(summary.at("seconds").at("linear_solve").get<double>(), 0);
  EXPECT_GT(summary.at("factorizations").get<int>(), 0);
  // The counters up to that step, under the keys of a finished run's summary.
  EXPECT_GT(summary.at("steps").get<int>(), 0);
  EXPECT_GT(summary.at("newton_iterations").get<int>(), 0);
  EXPECT_GT(summary.at("time_reached").get<double>(), 0);
  for (const char* key : {"step_cuts", "outputs", "min_time_step", "max_time_step"})
    EXPECT_TRUE(summary.contains(key)) << key;
  EXPECT_TRUE(fs::exists(output / "last_converged.vtu"));

  const CommandResult resumed = run_sinew(arguments(output, {"--resume"}), directory);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_THAT(resumed.err, HasSubstr("resuming after step"));
  expect_same_csv(reference / "steps.csv", output / "steps.csv", 1e-9);
  expect_same_csv(reference / "newton.csv", output / "newton.csv", 1e-4);
  expect_same_csv(reference / "rigid_bodies.csv", output / "rigid_bodies.csv", 1e-9);
  expect_same_vtu_set(reference, output);
}

TEST_F(Resume, SigtermAlsoEndsTheRunGracefully) {
  write_text(scene_path, adaptive_blocks_scene().dump(2));
  int status = 0;
  // After the run has taken its output directory (its handlers are installed a moment later).
  for (int delay_ms : {100, 50, 200, 20}) {
    fs::remove_all(output);
    status = run_and_signal(arguments(output), directory,
                            SignalPlan{.signal = SIGTERM, .ready = output / ".sinew.lock",
                                       .delay = std::chrono::milliseconds(delay_ms)})
                 .status;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 6) break;
  }
  ASSERT_TRUE(WIFEXITED(status)) << "ended by a signal";
  ASSERT_EQ(WEXITSTATUS(status), 6);
  const json summary = json::parse(read_text(output / "summary.json"));
  const std::string message = summary.at("message");
  EXPECT_THAT(message, ::testing::AnyOf(HasSubstr("interrupted by SIGTERM at lambda = "),
                                        HasSubstr("interrupted by SIGTERM before the first step")));
  EXPECT_TRUE(summary.contains("lambda_reached"));
  if (message.find("at lambda = ") != std::string::npos) {
    // A step was accepted: the counters up to it, the stabilization's included.
    EXPECT_GT(summary.at("steps").get<int>(), 0);
    for (const char* key : {"newton_iterations", "step_cuts", "snap_throughs", "stabilized_steps",
                            "stabilization_dissipated_energy", "stabilization_energy_ratio"})
      EXPECT_TRUE(summary.contains(key)) << key;
  } else {
    EXPECT_FALSE(summary.contains("steps"));
  }
}

TEST_F(Resume, ACheckpointOfAnotherSceneIsRefusedAndNothingIsWritten) {
  write_text(scene_path, small_block_scene().dump(2));
  ASSERT_EQ(run_sinew(arguments(output), directory).exit_code, 0);
  const std::string steps = read_text(output / "steps.csv");
  json changed = small_block_scene();
  changed["materials"]["rubber"]["C1"] = 0.6;
  write_text(scene_path, changed.dump(2));
  const CommandResult result = run_sinew(arguments(output, {"--resume"}), directory);
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_THAT(result.err, HasSubstr("belongs to another scene"));
  EXPECT_EQ(read_text(output / "steps.csv"), steps);
}

TEST_F(Resume, NoCheckpointADamagedOneAndResumeWithOverwriteAreRefusedClearly) {
  write_text(scene_path, small_block_scene().dump(2));
  CommandResult result = run_sinew(arguments(output, {"--resume"}), directory);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("does not exist: there is no run to resume"));

  ASSERT_EQ(run_sinew(arguments(output), directory).exit_code, 0);
  result = run_sinew(arguments(output, {"--resume", "--overwrite"}), directory);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("give one of them"));

  write_text(output / "checkpoint.cbor", "not a checkpoint at all");
  result = run_sinew(arguments(output, {"--resume"}), directory);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("is not a usable sinew checkpoint"));
  EXPECT_THAT(result.err, ::testing::Not(HasSubstr("scene \"")));  // refused before meshing

  fs::remove(output / "checkpoint.cbor");
  result = run_sinew(arguments(output, {"--resume"}), directory);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("there is no checkpoint in"));
  EXPECT_THAT(result.err, HasSubstr("--overwrite"));
}

TEST_F(Resume, AFinishedRunResumesToTheSameResults) {
  write_text(scene_path, small_block_scene().dump(2));
  ASSERT_EQ(run_sinew(arguments(output), directory).exit_code, 0);
  const std::string steps = read_text(output / "steps.csv");
  const CommandResult result = run_sinew(arguments(output, {"--resume"}), directory);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(read_text(output / "steps.csv"), steps);
}

}  // namespace
}  // namespace sinew::app_test
