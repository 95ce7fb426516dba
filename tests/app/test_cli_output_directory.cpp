/// @file test_cli_output_directory.cpp
/// A run's output directory is its own (docs/output-directory.md): checked before any work,
/// locked while a run writes into it, never mixed with an earlier run's files, and never the
/// root of the file system by accident. Through the real executable.

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "app/app_test_support.hpp"

namespace sinew::app_test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

class OutputDirectory : public ::testing::Test {
 protected:
  TempDir directory;
  fs::path scene_path = directory / "scene.json";
  fs::path output = directory / "out";

  void SetUp() override { write_text(scene_path, small_block_scene().dump(2)); }
  CommandResult run(const std::vector<std::string>& extra = {}) {
    std::vector<std::string> arguments{"run", scene_path.string(), "-o", output.string(), "--no-progress"};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    return run_sinew(arguments, directory);
  }
};

// `-o ""` once wrote steps.csv, vtu/ and the rest into "/" (the empty path's parent).
TEST_F(OutputDirectory, AnEmptyPathIsRejectedBeforeAnyWork) {
  const CommandResult result = run_sinew({"run", scene_path.string(), "-o", "", "--no-progress"}, directory);
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_THAT(result.err, HasSubstr("the output directory is empty"));
  EXPECT_THAT(result.err, Not(HasSubstr("scene \"")));  // refused before the scene was meshed
}

TEST_F(OutputDirectory, AFileInTheWayIsRejectedBeforeMeshing) {
  write_text(output, "not a directory");
  const CommandResult result = run();
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_THAT(result.err, HasSubstr("exists and is not a directory"));
  EXPECT_THAT(result.err, Not(HasSubstr("scene \"")));
  EXPECT_EQ(read_text(output), "not a directory");
}

TEST_F(OutputDirectory, ASecondRunIntoALockedDirectoryIsRefusedAndNamesTheFirst) {
  // Hold the lock as a running sinew does.
  fs::create_directories(output);
  const fs::path lock_path = output / ".sinew.lock";
  const int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const std::string holder = "pid 4242, started 2026-11-29 10:00:00 UTC, sinew run first.json\n";
  ASSERT_EQ(::write(fd, holder.data(), holder.size()), static_cast<ssize_t>(holder.size()));
  const CommandResult second = run({"--overwrite"});
  EXPECT_EQ(second.exit_code, 1) << second.err;
  EXPECT_THAT(second.err, HasSubstr("is in use by another sinew run (pid 4242"));
  EXPECT_THAT(second.err, HasSubstr("sinew run first.json"));
  EXPECT_FALSE(fs::exists(output / "steps.csv"));
  ::close(fd);  // the first run ends: the directory is free
  const CommandResult third = run({"--overwrite"});
  EXPECT_EQ(third.exit_code, 0) << third.err;
}

TEST_F(OutputDirectory, AnEarlierRunIsNeverMixedWithThisOne) {
  ASSERT_EQ(run().exit_code, 0);
  // Files an earlier, longer or failed run would leave behind.
  write_text(output / "last_converged.vtu", "stale");
  write_text(output / "vtu" / "increment_0009.vtu", "stale");
  const CommandResult refused = run();
  EXPECT_EQ(refused.exit_code, 1) << refused.err;
  EXPECT_THAT(refused.err, HasSubstr("is not empty"));
  EXPECT_THAT(refused.err, HasSubstr("--overwrite"));
  EXPECT_TRUE(fs::exists(output / "last_converged.vtu"));  // refused: nothing touched

  const CommandResult replaced = run({"--overwrite"});
  ASSERT_EQ(replaced.exit_code, 0) << replaced.err;
  EXPECT_FALSE(fs::exists(output / "last_converged.vtu"));
  EXPECT_FALSE(fs::exists(output / "vtu" / "increment_0009.vtu"));
  EXPECT_TRUE(fs::exists(output / "vtu" / "increment_0002.vtu"));
  EXPECT_TRUE(fs::exists(output / "summary.json"));
  // The lock file records the run that wrote the directory.
  EXPECT_THAT(read_text(output / ".sinew.lock"), HasSubstr("sinew run " + scene_path.string()));
}

TEST_F(OutputDirectory, ADirectorySinewDidNotWriteIsNeverEmptied) {
  fs::create_directories(output);
  write_text(output / "thesis.tex", "precious");
  const CommandResult result = run({"--overwrite"});
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_THAT(result.err, HasSubstr("was not written by sinew"));
  EXPECT_EQ(read_text(output / "thesis.tex"), "precious");
}

TEST_F(OutputDirectory, AnEmptyExistingDirectoryIsUsed) {
  fs::create_directories(output);
  EXPECT_EQ(run().exit_code, 0);
  EXPECT_TRUE(fs::exists(output / "summary.json"));
}

// When no load step converges, the logs still hold their header and the iterations tried.
TEST_F(OutputDirectory, LogsAreWrittenEvenWhenNoStepConverges) {
  json scene = small_block_scene();
  scene["boundary_conditions"][1]["motion"]["translation"] = {0, 0, -30};
  scene["solver"]["increments"] = 1;
  scene["solver"]["min_step"] = 0.3;
  write_text(scene_path, scene.dump(2));
  const CommandResult result = run();
  EXPECT_EQ(result.exit_code, 2) << result.err;
  ASSERT_TRUE(fs::is_regular_file(output / "steps.csv"));
  ASSERT_TRUE(fs::is_regular_file(output / "newton.csv"));
  EXPECT_THAT(read_text(output / "steps.csv"), HasSubstr("lambda"));
  const std::string newton = read_text(output / "newton.csv");
  EXPECT_GE(std::count(newton.begin(), newton.end(), '\n'), 2);  // the header and the iterations at lambda = 0
  const json summary = json::parse(read_text(output / "summary.json"));
  EXPECT_EQ(summary.at("status"), "stopped");
}

// A full disk in the middle of a run: exit code 3, the files written before complete, and
// summary.json saying where the run stopped when there is room for it. Needs a small tmpfs
// (root in a sandbox that allows mounts); skipped elsewhere.
TEST_F(OutputDirectory, AFullDiskMidRunIsItsOwnExitCode) {
  const SmallTmpfs disk(output);
  if (!disk.mounted()) GTEST_SKIP() << "cannot mount a small tmpfs here";
  json scene = small_block_scene();
  scene["bodies"][0]["mesh"]["generate"]["element_size"] = 1.5;  // VTUs larger than the disk
  scene["solver"]["increments"] = 4;
  write_text(scene_path, scene.dump(2));
  const CommandResult result = run();
  EXPECT_EQ(result.exit_code, 3) << result.err;
  EXPECT_THAT(result.err, HasSubstr("cannot write file"));
  for (const auto& file : files_under(output)) {
    EXPECT_EQ(file.find(".tmp."), std::string::npos) << "temporary file left behind: " << file;
    if (file.ends_with(".vtu")) {
      EXPECT_THAT(read_text(output / file), HasSubstr("</VTKFile>")) << file;
    }
  }
  if (fs::exists(output / "summary.json")) {
    const json summary = json::parse(read_text(output / "summary.json"));
    EXPECT_EQ(summary.at("status"), "output_error");
    EXPECT_TRUE(summary.contains("lambda_reached"));
  }
}

}  // namespace
}  // namespace sinew::app_test
