/// @file test_cli_bad_input.cpp
/// `sinew run` on bad input, through the real executable: exit code 1, a message that names
/// the key path or file and the problem, and nothing written (the output directory is never
/// created). And a solve that cannot succeed: exit code 2 with the last converged state.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "app/app_test_support.hpp"

namespace sinew::app_test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

/// A scratch directory holding a scene file; `run()` solves it into "<dir>/out".
class BadInput : public ::testing::Test {
 protected:
  TempDir directory;
  fs::path scene_path = directory / "scene.json";
  fs::path output = directory / "out";

  void write_scene(const json& scene) { write_text(scene_path, scene.dump(2)); }

  /// Runs the scene and checks what every rejected input must do: exit code 1, a message on
  /// standard error, nothing on disk.
  CommandResult run_rejected() {
    const CommandResult result = run_scene_file(scene_path, output, directory);
    EXPECT_EQ(result.exit_code, 1) << result.err;
    EXPECT_THAT(result.err, HasSubstr("[error]"));
    EXPECT_FALSE(fs::exists(output)) << "the output directory was created for a rejected input";
    return result;
  }
};

TEST_F(BadInput, TruncatedJsonNamesFileLineAndColumn) {
  const std::string full = small_block_scene().dump(2);
  // Cut in the middle of the line holding "solver".
  const std::size_t cut = full.find("\"solver\"") + 4;
  const std::string truncated = full.substr(0, cut);
  write_text(scene_path, truncated);
  // The parser stops at the end of the input: on the last line, one column past its last character.
  const auto line = 1 + std::count(truncated.begin(), truncated.end(), '\n');
  const auto column = truncated.size() - truncated.rfind('\n');
  const CommandResult result = run_rejected();
  EXPECT_THAT(result.err, HasSubstr(scene_path.string() + ":" + std::to_string(line) + ":" + std::to_string(column) +
                                    ": malformed JSON"));
}

TEST_F(BadInput, UnknownSolverNameNamesItsPathAndTheAllowedNames) {
  json scene = small_block_scene();
  scene["solver"]["linear"] = {{"solver", "lu"}};
  write_scene(scene);
  const CommandResult result = run_rejected();
  EXPECT_THAT(result.err, HasSubstr("solver.linear.solver: "));
  EXPECT_THAT(result.err, HasSubstr("\"cholmod\", \"gmres\", \"cg\""));
  EXPECT_THAT(result.err, HasSubstr("\"lu\""));
}

TEST_F(BadInput, UnknownKeyNamesItsPathAndSuggestsTheCloseSpelling) {
  json scene = small_block_scene();
  scene["solver"]["newton"] = {{"max_iteration", 10}};
  write_scene(scene);
  const CommandResult result = run_rejected();
  EXPECT_THAT(result.err, HasSubstr("solver.newton.max_iteration: unknown key"));
  EXPECT_THAT(result.err, HasSubstr("did you mean \"max_iterations\"?"));
  EXPECT_THAT(result.err, HasSubstr(scene_path.string()));
}

TEST_F(BadInput, UnknownKeyFarFromAnyNameListsTheAllowedKeys) {
  json scene = small_block_scene();
  scene["solver"]["zzzzzzzzzzzz"] = 1;
  write_scene(scene);
  const CommandResult result = run_rejected();
  EXPECT_THAT(result.err, HasSubstr("solver.zzzzzzzzzzzz: unknown key"));
  EXPECT_THAT(result.err, Not(HasSubstr("did you mean")));
  EXPECT_THAT(result.err, HasSubstr("\"increments\""));
}

TEST_F(BadInput, WrongTypeNamesThePathTheTypeAndTheValue) {
  json scene = small_block_scene();
  scene["solver"]["increments"] = "ten";
  write_scene(scene);
  const CommandResult result = run_rejected();
  EXPECT_THAT(result.err, HasSubstr("solver.increments: must be"));
  EXPECT_THAT(result.err, HasSubstr("integer"));
  EXPECT_THAT(result.err, HasSubstr("\"ten\""));
}

TEST_F(BadInput, MissingRequiredKeyIsNamed) {
  json scene = small_block_scene();
  scene.erase("units");
  write_scene(scene);
  const CommandResult result = run_rejected();
  EXPECT_THAT(result.err, HasSubstr("units: missing required key"));
}

TEST_F(BadInput, MissingMeshFileIsNamedWithItsPath) {
  json scene = small_block_scene();
  scene["bodies"][0]["mesh"] = {{"file", "no-such-mesh.msh"}};
  write_scene(scene);
  const CommandResult result = run_rejected();
  EXPECT_THAT(result.err, HasSubstr("bodies[0].mesh.file"));
  EXPECT_THAT(result.err, HasSubstr("not found"));
  EXPECT_THAT(result.err, HasSubstr((directory / "no-such-mesh.msh").string()));
}

// ---------------------------------------------------------------------------------------------
// Broken .msh files (Gmsh 2.2 ASCII, written by hand): two tets sharing the face (2, 3, 4).

std::string msh_file(const std::string& nodes, const std::string& elements) {
  return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
         "$PhysicalNames\n1\n3 1 \"rubber\"\n$EndPhysicalNames\n"
         "$Nodes\n5\n" + nodes + "$EndNodes\n"
         "$Elements\n2\n" + elements + "$EndElements\n";
}

const std::string kNodes = "1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n";

class BadMesh : public BadInput {
 protected:
  fs::path mesh_path = directory / "broken.msh";

  CommandResult run_mesh(const std::string& msh) {
    write_text(mesh_path, msh);
    json scene = small_block_scene();
    scene["bodies"][0]["mesh"] = {{"file", "broken.msh"}};
    scene["bodies"][0]["regions"] = {{"*", {{"material", "rubber"}}}};
    scene["boundary_conditions"] = json::array();
    write_scene(scene);
    const CommandResult result = run_rejected();
    EXPECT_THAT(result.err, HasSubstr(mesh_path.string()));
    return result;
  }
};

TEST_F(BadMesh, ValidTwoTetMeshIsAccepted) {
  // The control: the same file with both tets positive validates.
  write_text(mesh_path, msh_file(kNodes, "1 4 2 1 1 1 2 3 4\n2 4 2 1 1 2 3 4 5\n"));
  json scene = small_block_scene();
  scene["bodies"][0]["mesh"] = {{"file", "broken.msh"}};
  scene["bodies"][0]["regions"] = {{"*", {{"material", "rubber"}}}};
  scene["boundary_conditions"] = json::array();
  write_scene(scene);
  const CommandResult result = run_sinew({"validate", scene_path.string()}, directory);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_THAT(result.out, HasSubstr("valid (1 bodies, 5 nodes, 2 tets"));
}

TEST_F(BadMesh, InvertedTetIsRejected) {
  // Node 5 at (0.1, 0.1, 0.1) lies on node 1's side of the shared face (2, 3, 4): the second tet
  // is turned inside out and overlaps the first (negative volume in the first tet's winding).
  const std::string nodes = "1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 0.1 0.1 0.1\n";
  const CommandResult result = run_mesh(msh_file(nodes, "1 4 2 1 1 1 2 3 4\n2 4 2 1 1 2 3 4 5\n"));
  EXPECT_THAT(result.err, HasSubstr("1 inverted tetra"));
}

TEST_F(BadMesh, ZeroVolumeTetIsRejected) {
  // Node 5 at (1, 1, 0) lies in the plane of nodes 1, 2, 3.
  const std::string nodes = "1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 0\n";
  const CommandResult result = run_mesh(msh_file(nodes, "1 4 2 1 1 1 2 3 4\n2 4 2 1 1 1 2 3 5\n"));
  EXPECT_THAT(result.err, HasSubstr("1 zero-volume tetrahedron"));
  EXPECT_THAT(result.err, HasSubstr("tet 1 (1-based 2"));
}

TEST_F(BadMesh, DuplicateTetIsRejected) {
  const CommandResult result = run_mesh(msh_file(kNodes, "1 4 2 1 1 1 2 3 4\n2 4 2 1 1 2 1 4 3\n"));
  EXPECT_THAT(result.err, HasSubstr("1 duplicate tetrahedron (same four nodes)"));
  EXPECT_THAT(result.err, HasSubstr("repeats tet 0"));
}

// ---------------------------------------------------------------------------------------------
// Numbers out of range.

TEST_F(BadInput, NanAsAStringIsAWrongType) {
  json scene = small_block_scene();
  scene["materials"]["rubber"]["C1"] = "nan";
  write_scene(scene);
  const CommandResult result = run_rejected();
  EXPECT_THAT(result.err, HasSubstr("materials.rubber.C1: must be"));
  EXPECT_THAT(result.err, HasSubstr("number"));
  EXPECT_THAT(result.err, HasSubstr("\"nan\""));
}

TEST_F(BadInput, OverflowingNumberIsRejectedClearly) {
  // 1e999 overflows a double. nlohmann::json 3.11 refuses it while parsing (out_of_range.406,
  // "number overflow parsing '1e999'"), so the key path is not known yet: the message must name
  // the scene file and the offending number, like any other malformed JSON, and exit with 1.
  json scene = small_block_scene();
  scene["materials"]["rubber"]["C1"] = 123456.5;
  std::string text = scene.dump(2);
  const std::size_t at = text.find("123456.5");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 8, "1e999");
  write_text(scene_path, text);
  const CommandResult result = run_rejected();
  EXPECT_THAT(result.err, HasSubstr(scene_path.string()));
  EXPECT_THAT(result.err, HasSubstr("1e999"));
  EXPECT_THAT(result.err, Not(HasSubstr("terminate called")));
}

TEST_F(BadInput, NegativeStiffnessIsOutOfRange) {
  json scene = small_block_scene();
  scene["materials"]["rubber"]["C1"] = -1;
  write_scene(scene);
  const CommandResult result = run_rejected();
  EXPECT_THAT(result.err, HasSubstr("materials.rubber.C1: must be > 0, got -1"));
}

TEST_F(BadInput, NegativeDensityIsOutOfRange) {
  json scene = small_block_scene();
  scene["bodies"][0]["regions"]["rubber"]["density"] = -1000;
  write_scene(scene);
  const CommandResult result = run_rejected();
  EXPECT_THAT(result.err, HasSubstr("bodies[0].regions.rubber.density: must be >= 0, got -1000"));
}

TEST_F(BadInput, BoundaryConditionSelectingNoNode) {
  json scene = small_block_scene();
  scene["boundary_conditions"][1]["nodes"]["plane"]["point"] = {0, 0, 100};
  write_scene(scene);
  const CommandResult result = run_rejected();
  EXPECT_THAT(result.err, HasSubstr("boundary_conditions[1].nodes: selects no node"));
}

TEST_F(BadInput, UnknownMaterialNameSuggestsTheCloseOne) {
  json scene = small_block_scene();
  scene["bodies"][0]["regions"]["rubber"]["material"] = "rubbr";
  write_scene(scene);
  const CommandResult result = run_rejected();
  EXPECT_THAT(result.err, HasSubstr("bodies[0].regions.rubber.material: unknown material \"rubbr\""));
  EXPECT_THAT(result.err, HasSubstr("did you mean \"rubber\"?"));
}

TEST_F(BadInput, MissingSceneFileIsNamed) {
  const fs::path missing = directory / "no-such-scene.json";
  const CommandResult result = run_scene_file(missing, output, directory);
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_THAT(result.err, HasSubstr(missing.string()));
  EXPECT_THAT(result.err, HasSubstr("not found"));
  EXPECT_FALSE(fs::exists(output));
}

// ---------------------------------------------------------------------------------------------
// A motion no solid can follow: the top face pushed through the bottom one.

TEST_F(BadInput, ImpossibleMotionStopsWithExitCode2AndKeepsTheLastConvergedState) {
  json scene = small_block_scene();
  scene["boundary_conditions"][1]["motion"]["translation"] = {0, 0, -12};
  scene["solver"]["increments"] = 4;
  scene["solver"]["min_step"] = 0.01;
  write_scene(scene);
  const CommandResult result = run_scene_file(scene_path, output, directory);
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_THAT(result.err, HasSubstr("load step from lambda ="));
  EXPECT_THAT(result.err, HasSubstr("could not be solved"));
  // Stuck, the steps went on with the viscous stabilization (solver.stabilization), which cannot
  // squeeze a block through itself either.
  EXPECT_THAT(result.err, HasSubstr("Going on with viscous stabilization"));
  EXPECT_THAT(result.err, HasSubstr("with the viscous stabilization on"));
  EXPECT_THAT(result.err, HasSubstr("last_converged.vtu"));
  ASSERT_TRUE(fs::is_directory(output));
  EXPECT_TRUE(fs::is_regular_file(output / "last_converged.vtu"));
  EXPECT_TRUE(fs::is_regular_file(output / "steps.csv"));
  ASSERT_TRUE(fs::is_regular_file(output / "summary.json"));
  const json summary = json::parse(read_text(output / "summary.json"));
  EXPECT_EQ(summary.at("success"), false);
  EXPECT_THAT(summary.at("message").get<std::string>(), HasSubstr("could not be solved"));
  // The block can be squeezed most of the way, not through its own bottom (lambda = 10/12).
  const double reached = summary.at("lambda_reached").get<double>();
  EXPECT_GT(reached, 0.0);
  EXPECT_LT(reached, 10.0 / 12.0);
}

TEST_F(BadInput, ValidateChecksTheContactSetupLikeARun) {
  // A depth field on a generated mesh only fails when the contact term is built: validate must
  // build it too, and say the same as run.
  json scene = small_block_scene();
  scene["bodies"][0]["contact"] = {{"depth_field", "thickness"}};
  scene["contact"] = {{"self_contact", true}};
  write_scene(scene);
  const CommandResult validated = run_sinew({"validate", scene_path.string()}, directory);
  EXPECT_EQ(validated.exit_code, 1) << validated.out;
  EXPECT_THAT(validated.err, HasSubstr("bodies[0].contact.depth_field:"));
  const CommandResult result = run_rejected();
  EXPECT_THAT(result.err, HasSubstr("bodies[0].contact.depth_field:"));
  // The control: without the field, validate reports the contact and the dynamics it checked.
  scene["bodies"][0].erase("contact");
  scene["dynamics"] = {{"integrator", "implicit-euler"}, {"end_time", 1.0}, {"output_interval", 0.5}};
  write_scene(scene);
  const CommandResult valid = run_sinew({"validate", scene_path.string()}, directory);
  EXPECT_EQ(valid.exit_code, 0) << valid.err;
  EXPECT_THAT(valid.out, HasSubstr("contact between 1 bodies, dynamics)"));
}

// The same impossible motion in time: an implicit step halved below min_time_step, and an
// explicit run stopped by the first inverted element. Both keep what was written and say why.

TEST_F(BadInput, ImplicitStepBelowMinTimeStepStopsWithExitCode2AndKeepsTheLastConvergedState) {
  json scene = small_block_scene();
  scene["boundary_conditions"][1]["motion"]["translation"] = {0, 0, -12};
  scene["dynamics"] = {{"integrator", "implicit-euler"}, {"end_time", 1.0}, {"output_interval", 0.25},
                       {"time_step", 0.05}, {"min_time_step", 0.01}};
  write_scene(scene);
  const CommandResult result = run_scene_file(scene_path, output, directory);
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_THAT(result.err, HasSubstr("could not be solved even with h ="));
  EXPECT_THAT(result.err, HasSubstr("(min_time_step 0.01)"));
  EXPECT_THAT(result.err, HasSubstr("last_converged.vtu"));
  EXPECT_TRUE(fs::is_regular_file(output / "last_converged.vtu"));
  ASSERT_TRUE(fs::is_regular_file(output / "summary.json"));
  const json summary = json::parse(read_text(output / "summary.json"));
  EXPECT_EQ(summary.at("success"), false);
  EXPECT_THAT(summary.at("message").get<std::string>(), HasSubstr("min_time_step"));
  // Squeezed most of the way in time (the motion is linear over end_time), not through the bottom.
  const double reached = summary.at("time_reached").get<double>();
  EXPECT_GT(reached, 0.25);
  EXPECT_LT(reached, 10.0 / 12.0);
  // The log holds every completed step, the last one at the time reached.
  const std::string steps = read_text(output / "steps.csv");
  EXPECT_NE(steps.find("time"), std::string::npos);
  EXPECT_GT(std::count(steps.begin(), steps.end(), '\n'), 2);
}

TEST_F(BadInput, ExplicitRunStopsAtTheFirstInvertedElementWithExitCode2) {
  json scene = small_block_scene();
  scene["boundary_conditions"][1]["motion"]["translation"] = {0, 0, -12};
  scene["dynamics"] = {{"integrator", "explicit"}, {"end_time", 1.0}, {"output_interval", 0.25}};
  write_scene(scene);
  const CommandResult result = run_scene_file(scene_path, output, directory);
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_THAT(result.err, HasSubstr("explicit integration: an element inverted at t ="));
  EXPECT_THAT(result.err, HasSubstr("lower explicit_safety (now 0.5) or use the implicit integrator"));
  EXPECT_TRUE(fs::is_regular_file(output / "last_converged.vtu"));
  ASSERT_TRUE(fs::is_regular_file(output / "summary.json"));
  const json summary = json::parse(read_text(output / "summary.json"));
  EXPECT_EQ(summary.at("success"), false);
  const double reached = summary.at("time_reached").get<double>();
  EXPECT_GT(reached, 0.25);
  EXPECT_LT(reached, 10.0 / 12.0);
  // The outputs before the failure are complete VTUs listed in the series.
  const std::string pvd = read_text(output / "sinew.pvd");
  EXPECT_NE(pvd.find("vtu/output_0000.vtu"), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(output / "vtu" / "output_0000.vtu"));
}

}  // namespace
}  // namespace sinew::app_test
