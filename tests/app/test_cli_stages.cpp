/// @file test_cli_stages.cpp
/// Sequential stages through the real executable (docs/stages.md): a scene whose
/// "initial_state" names a finished run's output directory goes on from there and ends where one
/// run of both stages ends; a start that cannot be used (no run, an interrupted one) is refused
/// by `sinew run` and `sinew validate` with exit code 1 before anything is written (the model's
/// tests, test_stage_start.cpp, cover an unfinished run, other meshes and damaged files).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "app/app_test_support.hpp"

namespace sinew::app_test {
namespace {

using ::testing::HasSubstr;

/// The last row of a CSV file, split at commas, by column name.
std::map<std::string, std::string> last_row(const fs::path& csv) {
  std::istringstream in(read_text(csv));
  std::string header, line, last;
  std::getline(in, header);
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  auto split = [](const std::string& text) {
    std::vector<std::string> cells;
    std::stringstream s(text);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    return cells;
  };
  const auto names = split(header), values = split(last);
  std::map<std::string, std::string> row;
  for (std::size_t i = 0; i < names.size() && i < values.size(); ++i) row[names[i]] = values[i];
  return row;
}

class Stages : public ::testing::Test {
 protected:
  TempDir directory;

  /// The small block pressed `push` mm in `increments` increments, written as `name`.json.
  fs::path write_scene(const std::string& name, double push, int increments, const std::string& initial_state = "") {
    json scene = small_block_scene();
    scene["boundary_conditions"][1]["motion"]["translation"] = {0, 0, -push};
    scene["solver"]["increments"] = increments;
    if (!initial_state.empty()) scene["initial_state"] = initial_state;
    const fs::path path = directory / (name + ".json");
    write_text(path, scene.dump(2));
    return path;
  }
  CommandResult run(const fs::path& scene, const std::string& out) {
    return run_sinew({"run", scene.string(), "-o", (directory / out).string(), "--no-progress"}, directory);
  }
};

TEST_F(Stages, TwoStagesEndWhereOneRunOfBothEnds) {
  ASSERT_EQ(run(write_scene("whole", 2, 4), "whole").exit_code, 0);
  ASSERT_EQ(run(write_scene("first", 1, 2), "first").exit_code, 0);
  // "initial_state" is relative to the scene file's directory.
  const CommandResult second = run(write_scene("second", 1, 2, "first"), "second");
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_THAT(second.err, HasSubstr("starting from the end of the run in"));
  const auto whole = last_row(directory / "whole" / "steps.csv");
  const auto staged = last_row(directory / "second" / "steps.csv");
  for (const char* column : {"energy", "top.fz", "bottom.fz"}) {
    const double a = std::stod(whole.at(column)), b = std::stod(staged.at(column));
    EXPECT_NEAR(a, b, 1e-8 * std::abs(a)) << column;
  }
  // The second stage is a run of its own: it can be a stage's start in turn (3 mm: the top is
  // pushed down harder than after 2 mm).
  ASSERT_EQ(run(write_scene("third", 1, 2, "second"), "third").exit_code, 0);
  EXPECT_LT(std::stod(last_row(directory / "third" / "steps.csv").at("top.fz")), 1.2 * std::stod(whole.at("top.fz")));
}

TEST_F(Stages, AStartThatCannotBeUsedIsRefusedBeforeAnythingIsWritten) {
  const fs::path second = write_scene("second", 1, 2, "first");
  CommandResult result = run(second, "second");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("initial_state"));
  EXPECT_THAT(result.err, HasSubstr("no such directory"));
  EXPECT_FALSE(fs::exists(directory / "second"));
  result = run_sinew({"validate", second.string()}, directory);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("no such directory"));

  // An output directory without a checkpoint (a run of an older sinew, or explicit integration).
  ASSERT_EQ(run(write_scene("first", 1, 2), "first").exit_code, 0);
  fs::remove(directory / "first" / "checkpoint.cbor");
  result = run(second, "second");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("holds no checkpoint.cbor"));
  EXPECT_FALSE(fs::exists(directory / "second"));
}

TEST_F(Stages, AStageIsNotWrittenOverTheRunItStartsFrom) {
  ASSERT_EQ(run(write_scene("first", 1, 2), "first").exit_code, 0);
  const std::string steps = read_text(directory / "first" / "steps.csv");
  const CommandResult result = run_sinew(
      {"run", write_scene("second", 1, 2, "first").string(), "-o", (directory / "first").string(), "--overwrite",
       "--no-progress"},
      directory);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("is the run this scene starts from"));
  EXPECT_EQ(read_text(directory / "first" / "steps.csv"), steps);
}

}  // namespace
}  // namespace sinew::app_test
