/// @file test_cli_commands.cpp
/// The `sinew` command line through the real executable: validate, schema, help, and a
/// successful run that leaves no temporary file behind.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>

#include "app/app_test_support.hpp"

namespace sinew::app_test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

TEST(Cli, ValidateAcceptsEveryExample) {
  TempDir directory;
  int examples = 0;
  for (const auto& entry : fs::directory_iterator(kSource / "examples")) {
    if (entry.path().extension() != ".json") continue;
    ++examples;
    std::vector<std::string> arguments{"validate", entry.path().string()};
    if (entry.path().stem() == "vh-knee-flexion") {
      // Reads the Visible Human surfaces from ../shared beside the repository, when they are there.
      if (!fs::exists(kSource / ".." / "shared" / "data" / "vh-knee" / "VH_M_Knee_R.glb")) {
        std::printf("[ skipped  ] %s: the VH knee data is not at ../shared/data/vh-knee\n", entry.path().c_str());
        continue;
      }
#ifdef SINEW_SANITIZER_BUILD
      std::printf("[ skipped  ] %s: meshing the VH surfaces instrumented takes minutes\n", entry.path().c_str());
      continue;
#endif
      arguments.insert(arguments.end(), {"--element-size", "30"});  // meshing at the scene's 22 mm takes a minute and a half
    }
    const CommandResult result = run_sinew(arguments, directory);
    EXPECT_EQ(result.exit_code, 0) << entry.path() << "\n" << result.err;
    EXPECT_THAT(result.out, HasSubstr(entry.path().string() + ": valid")) << result.err;
  }
  EXPECT_GE(examples, 4);
}

TEST(Cli, ValidateWritesNothing) {
  TempDir directory;
  const fs::path scene = directory / "scene.json";
  write_text(scene, small_block_scene().dump(2));
  const CommandResult result = run_sinew({"validate", scene.string()}, directory);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_THAT(result.out, HasSubstr("valid"));
  EXPECT_FALSE(fs::exists(directory / "out"));
}

/// The number before " nodes" in validate's or run's report.
int reported_nodes(const std::string& text) {
  const auto at = text.find(" nodes");
  if (at == std::string::npos) return -1;
  auto start = text.rfind(' ', at - 1);
  return std::stoi(text.substr(start + 1, at - start - 1));
}

TEST(Cli, ElementSizeOverridesEveryGeneratedMesh) {
  TempDir directory;
  const fs::path scene = directory / "scene.json";
  write_text(scene, small_block_scene().dump(2));  // element_size 5
  const CommandResult as_written = run_sinew({"validate", scene.string()}, directory);
  const CommandResult finer = run_sinew({"validate", scene.string(), "--element-size", "2"}, directory);
  ASSERT_EQ(as_written.exit_code, 0) << as_written.err;
  ASSERT_EQ(finer.exit_code, 0) << finer.err;
  EXPECT_GT(reported_nodes(finer.out), 4 * reported_nodes(as_written.out)) << as_written.out << finer.out;

  const CommandResult run = run_sinew(
      {"run", scene.string(), "--element-size", "2.5", "-o", (directory / "out").string(), "--no-progress"}, directory);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto summary = json::parse(read_text(directory / "out" / "summary.json"));
  EXPECT_GT(summary.at("nodes").get<int>(), 2 * reported_nodes(as_written.out));

  const CommandResult bad = run_sinew({"validate", scene.string(), "--element-size", "-1"}, directory);
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_THAT(bad.err + bad.out, HasSubstr("--element-size"));
}

TEST(Cli, RunOnAMissingSceneFileNamesIt) {
  TempDir directory;
  const fs::path missing = directory / "missing-scene.json";
  const CommandResult result = run_sinew({"run", missing.string(), "-o", (directory / "out").string()}, directory);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr(missing.string()));
  EXPECT_FALSE(fs::exists(directory / "out"));
}

TEST(Cli, ValidateOnAMissingSceneFileNamesIt) {
  TempDir directory;
  const fs::path missing = directory / "missing-scene.json";
  const CommandResult result = run_sinew({"validate", missing.string()}, directory);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr(missing.string()));
}

TEST(Cli, HelpExitsZeroAndListsTheCommands) {
  TempDir directory;
  const CommandResult result = run_sinew({"--help"}, directory);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  for (const char* command : {"run", "validate", "schema"}) EXPECT_THAT(result.out, HasSubstr(command));
}

TEST(Cli, NoCommandIsAUsageError) {
  TempDir directory;
  const CommandResult result = run_sinew({}, directory);
  EXPECT_NE(result.exit_code, 0);
}

TEST(Cli, SchemaMarkdownIsTheCommittedReference) {
  TempDir directory;
  const CommandResult result = run_sinew({"schema", "--markdown"}, directory);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  const std::string committed = read_text(kSource / "docs" / "scene-reference.md");
  if (result.out == committed) return;
  // Point at the first line that differs rather than printing both documents.
  std::istringstream printed_lines(result.out), committed_lines(committed);
  std::string printed_line, committed_line;
  int line = 0;
  while (true) {
    ++line;
    const bool has_printed = static_cast<bool>(std::getline(printed_lines, printed_line));
    const bool has_committed = static_cast<bool>(std::getline(committed_lines, committed_line));
    if (!has_printed && !has_committed) break;
    if (has_printed != has_committed || printed_line != committed_line) {
      ADD_FAILURE() << "docs/scene-reference.md differs from `sinew schema --markdown` at line " << line
                    << ":\n  printed:   " << (has_printed ? printed_line : "(end of output)")
                    << "\n  committed: " << (has_committed ? committed_line : "(end of file)")
                    << "\nregenerate it with `sinew schema --markdown > docs/scene-reference.md`";
      break;
    }
  }
  EXPECT_EQ(result.out.size(), committed.size());
}

TEST(Cli, SchemaJsonIsAJsonSchema) {
  TempDir directory;
  const CommandResult result = run_sinew({"schema", "--json"}, directory);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  json schema;
  ASSERT_NO_THROW(schema = json::parse(result.out));
  ASSERT_TRUE(schema.is_object());
  ASSERT_TRUE(schema.contains("$schema"));
  EXPECT_THAT(schema.at("$schema").get<std::string>(), HasSubstr("json-schema.org"));
  ASSERT_TRUE(schema.contains("properties"));
  for (const char* key : {"units", "materials", "bodies", "boundary_conditions", "loads", "solver", "output"}) {
    EXPECT_TRUE(schema.at("properties").contains(key)) << key;
  }
}

TEST(Cli, SchemaToAFileWritesTheSameText) {
  TempDir directory;
  const fs::path file = directory / "schema.json";
  const CommandResult to_file = run_sinew({"schema", "--json", "-o", file.string()}, directory);
  EXPECT_EQ(to_file.exit_code, 0) << to_file.err;
  const CommandResult to_stdout = run_sinew({"schema", "--json"}, directory);
  ASSERT_TRUE(fs::is_regular_file(file));
  EXPECT_EQ(read_text(file), to_stdout.out);
}

TEST(Cli, SuccessfulRunWritesEveryOutputAtomically) {
  TempDir directory;
  const fs::path scene = directory / "scene.json";
  const fs::path output = directory / "out";
  write_text(scene, small_block_scene().dump(2));
  const CommandResult result = run_scene_file(scene, output, directory);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  ASSERT_TRUE(fs::is_directory(output));
  for (const char* file : {"sinew.pvd", "steps.csv", "newton.csv", "summary.json", "vtu/increment_0000.vtu",
                           "vtu/increment_0001.vtu", "vtu/increment_0002.vtu"}) {
    EXPECT_TRUE(fs::is_regular_file(output / file)) << file;
  }
  EXPECT_FALSE(fs::exists(output / "last_converged.vtu"));
  // No temporary file ("." + name + ".tmp...") left anywhere in the tree; the one hidden file
  // is the directory's lock (docs/output-directory.md).
  for (const auto& path : files_under(output)) {
    if (path == ".sinew.lock") continue;
    EXPECT_THAT(fs::path(path).filename().string(), Not(StartsWith("."))) << path;
  }
  const json summary = json::parse(read_text(output / "summary.json"));
  EXPECT_EQ(summary.at("success"), true);
  EXPECT_EQ(summary.at("scene"), "small-block");
}

// A nearly incompressible block (bulk/shear ~ 1e6) at rest, with nothing to move it: its rest
// state was reported as "the initial state (lambda = 0) has no equilibrium" because the
// round-off of its elastic forces lay above a residual floor scaled by the shear modulus alone.
TEST(Cli, AStressFreeRestStateIsSolvedWithZeroDisplacement) {
  TempDir directory;
  const fs::path scene = directory / "scene.json";
  const fs::path output = directory / "out";
  json rest = small_block_scene();
  rest["materials"]["rubber"] = {{"law", "mooney-rivlin"}, {"C1", 0.2}, {"a", 1e6}};
  rest["bodies"][0]["mesh"]["generate"]["element_size"] = 2.0;
  rest["boundary_conditions"].erase(1);  // no motion, no load
  rest["output"]["vtu"] = false;
  write_text(scene, rest.dump(2));
  const CommandResult result = run_scene_file(scene, output, directory);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const json summary = json::parse(read_text(output / "summary.json"));
  EXPECT_EQ(summary.at("success"), true);
  EXPECT_EQ(summary.at("lambda_reached"), 1.0);
}

// `sinew study convergence` on a coarse, short variant of examples/convergence-corner.json.
json coarse_convergence_scene() {
  json scene = json::parse(read_text(kSource / "examples" / "convergence-corner.json"));
  scene["bodies"][0]["mesh"]["generate"]["element_size"] = 2.5;
  scene["bodies"][1]["mesh"]["generate"]["element_size"] = 2.5;
  scene["output"]["vtu"] = false;
  return scene;
}

TEST(Cli, StudyConvergencePrintsTheTableAndWritesItsFiles) {
  TempDir directory;
  const fs::path scene = directory / "scene.json";
  write_text(scene, coarse_convergence_scene().dump(2));
  const fs::path study = directory / "study";
  const CommandResult result =
      run_sinew({"study", "convergence", scene.string(), "-o", study.string(), "--penalties", "0,1000", "--methods",
                 "area", "--end-time", "5e-5", "--sweep-body", "right", "--sweep-translation", "0", "0", "-0.5",
                 "--sweep-positions", "3"},
                directory);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_THAT(result.out, HasSubstr("| penalty ε | area integration |"));
  EXPECT_THAT(result.out, HasSubstr("| 0 |"));
  EXPECT_THAT(result.out, HasSubstr("| 1000 |"));
  EXPECT_THAT(result.err, HasSubstr("scripts/plot_convergence_study.py"));
  for (const char* file : {"residuals.csv", "runs.csv", "penetration.md", "sweep_forces.csv", "sweep_totals.csv",
                           "sweep.json", "area-eps0/steps.csv", "area-eps1000/newton.csv"})
    EXPECT_TRUE(fs::is_regular_file(study / file)) << file;
  EXPECT_FALSE(fs::exists(study / "point-eps0")) << "only the methods asked for run";
}

TEST(Cli, StudyConvergenceRejectsBadOptionsBeforeWriting) {
  TempDir directory;
  const fs::path scene = directory / "scene.json";
  write_text(scene, coarse_convergence_scene().dump(2));
  const fs::path study = directory / "study";
  CommandResult result = run_sinew(
      {"study", "convergence", scene.string(), "-o", study.string(), "--sweep-body", "right"}, directory);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("--sweep-body needs --sweep-translation X Y Z"));
  result = run_sinew({"study", "convergence", scene.string(), "-o", study.string(), "--methods", "line"}, directory);
  EXPECT_NE(result.exit_code, 0);
  EXPECT_THAT(result.err + result.out, HasSubstr("line"));
  result = run_sinew({"study", "convergence", scene.string(), "-o", study.string(), "--penalties", "10,-5"}, directory);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.err, HasSubstr("penalty -5 must be finite and >= 0"));
  EXPECT_FALSE(fs::exists(study));
}

// A mesh far beyond the machine is refused from its estimate before meshing; --max-tets moves
// the limit both ways.
TEST(Cli, MaxTetsBoundsTheEstimatedMeshBeforeMeshing) {
  TempDir directory;
  const fs::path scene = directory / "scene.json";
  write_text(scene, small_block_scene().dump(2));  // 10 mm cube, element_size 5
  const CommandResult tiny = run_sinew({"validate", scene.string(), "--element-size", "0.01"}, directory);
  EXPECT_EQ(tiny.exit_code, 1) << tiny.err;
  EXPECT_THAT(tiny.err, HasSubstr("--max-tets"));
  const CommandResult tight = run_sinew({"validate", scene.string(), "--max-tets", "2"}, directory);
  EXPECT_EQ(tight.exit_code, 1) << tight.err;
  EXPECT_THAT(tight.err, HasSubstr("--max-tets"));
  const CommandResult allowed = run_sinew({"validate", scene.string(), "--max-tets", "1e4"}, directory);
  EXPECT_EQ(allowed.exit_code, 0) << allowed.err;
  const CommandResult nan = run_sinew({"validate", scene.string(), "--max-tets", "nan"}, directory);
  EXPECT_EQ(nan.exit_code, 1) << nan.err;
}

// A scene with nothing left to solve (a prescribed rigid body alone) once crashed the tangent
// predictor, which factorized a 0 x 0 stiffness; it runs to its end.
TEST(Cli, ASceneWithNoUnknownsRunsToItsEnd) {
  TempDir directory;
  const fs::path scene = directory / "scene.json";
  json j = small_block_scene();
  j["bodies"][0]["regions"]["rubber"] = {{"rigid", {{"prescribed", {{"translation", {1, 0, 0}}}}}}};
  j["boundary_conditions"] = json::array();
  write_text(scene, j.dump(2));
  const CommandResult result = run_scene_file(scene, directory / "out", directory);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_THAT(read_text(directory / "out" / "rigid_bodies.csv"), HasSubstr("block"));
}

}  // namespace
}  // namespace sinew::app_test
