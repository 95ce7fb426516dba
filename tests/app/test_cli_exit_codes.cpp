/// @file test_cli_exit_codes.cpp
/// Every command-line mistake exits 1 with a message that names it (CLI11's own codes,
/// 104-114, are not sinew's), --help exits 0 and lists the exit codes, and no input, however
/// wrong, ends sinew by a signal.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "app/app_test_support.hpp"

namespace sinew::app_test {
namespace {

using ::testing::HasSubstr;

/// The longest run of decimal digits in `text`.
std::size_t longest_digit_run(const std::string& text) {
  std::size_t longest = 0, run = 0;
  for (const char c : text) {
    run = (c >= '0' && c <= '9') ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  return longest;
}

struct Mistake {
  std::vector<std::string> arguments;  ///< "SCENE" stands for a valid scene file
  std::string named;                   ///< the message names this
};

TEST(ExitCodes, EveryCommandLineMistakeExitsOneAndNamesIt) {
  TempDir directory;
  const fs::path scene = directory / "scene.json";
  write_text(scene, small_block_scene().dump(2));
  const std::vector<Mistake> mistakes{
      {{}, "subcommand"},
      {{"--bogus"}, "--bogus"},
      {{"frobnicate"}, "frobnicate"},
      {{"run"}, "scene"},
      {{"run", "SCENE", "--bogus"}, "--bogus"},
      {{"run", "SCENE", "-j", "-1"}, "--threads"},
      {{"run", "SCENE", "-j", "abc"}, "abc"},
      {{"run", "SCENE", "-j", "99999999999999999999999"}, "--threads"},
      {{"run", "SCENE", "--element-size", "nan"}, "nan"},
      {{"run", "SCENE", "--element-size", "inf"}, "inf"},
      {{"run", "SCENE", "--element-size", "-1"}, "-1"},
      {{"run", "SCENE", "--element-size", "0"}, "finite number > 0"},
      {{"run", "SCENE", "--element-size", "1e400"}, "1e400"},
      {{"run", "SCENE", "--element-size"}, "--element-size"},
      {{"validate", "SCENE", "--element-size", "nan"}, "nan"},
      {{"validate"}, "scene"},
      {{"schema"}, "format"},
      {{"schema", "--markdown", "--json"}, "format"},
      {{"study"}, "subcommand"},
      {{"study", "convergence", "SCENE", "--methods", "foo"}, "foo"},
      {{"run", "SCENE", "-o"}, "-o"},
  };
  for (const auto& mistake : mistakes) {
    std::vector<std::string> arguments;
    std::string shown = "sinew";
    for (const auto& a : mistake.arguments) {
      arguments.push_back(a == "SCENE" ? scene.string() : a);
      shown += " " + a;
    }
    const CommandResult result = run_sinew(arguments, directory);
    EXPECT_EQ(result.exit_code, 1) << shown << "\n" << result.err;
    EXPECT_THAT(result.out + result.err, HasSubstr(mistake.named)) << shown;
    // Range messages print numbers as written, not as 309 digits.
    EXPECT_LT(longest_digit_run(result.out + result.err), 40u) << shown << "\n" << result.err;
  }
  EXPECT_FALSE(fs::exists(directory / "out"));
}

TEST(ExitCodes, HelpExitsZeroAndDocumentsEveryExitCode) {
  TempDir directory;
  for (const std::vector<std::string>& arguments :
       {std::vector<std::string>{"--help"}, std::vector<std::string>{"run", "--help"}}) {
    const CommandResult result = run_sinew(arguments, directory);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    if (arguments.size() == 1) {
      EXPECT_THAT(result.out, HasSubstr("Exit codes:"));
      for (const char* line : {"  0  done", "  1  the scene", "  2  the solve stopped", "  3  an output could not",
                               "  4  memory ran out", "  5  an internal error"})
        EXPECT_THAT(result.out, HasSubstr(line));
    }
  }
}

// An explicit ball drop whose rigid ground is free with density 0 once aborted `sinew run`
// (exit code 134) after `validate` had passed it.
TEST(ExitCodes, AFreeMasslessRigidBodyInAnExplicitRunIsAnInputError) {
  TempDir directory;
  json scene = json::parse(read_text(fs::path(SINEW_SOURCE_DIR) / "examples" / "ball-drop.json"));
  scene["bodies"][1]["regions"]["ground"] = {{"rigid", "free"}, {"density", 0}};
  scene["dynamics"]["integrator"] = "explicit";
  scene["dynamics"]["end_time"] = 0.001;
  scene["dynamics"]["output_interval"] = 0.001;
  const fs::path path = directory / "scene.json";
  write_text(path, scene.dump(2));
  // validate builds exactly the model run builds, so it refuses the scene too.
  const CommandResult validated = run_sinew({"validate", path.string()}, directory);
  EXPECT_EQ(validated.exit_code, 1) << validated.err;
  EXPECT_THAT(validated.err, HasSubstr("density"));
  const CommandResult result = run_scene_file(path, directory / "out", directory);
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_THAT(result.err, HasSubstr("density"));
  EXPECT_FALSE(fs::exists(directory / "out" / "summary.json")) << "nothing is written for an input error";
}

}  // namespace
}  // namespace sinew::app_test
