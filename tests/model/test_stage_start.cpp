/// @file test_stage_start.cpp
/// Sequential stages (model/stage_start.hpp, docs/stages.md): a static run split into two stages
/// ends where the same run in one stage ends; a dynamic stage goes on with the velocities of
/// the stage before it (bit for bit what one run with the same steps does); a rigid body keeps
/// the pose the earlier stage left it in; every start that cannot be used is refused with a
/// message naming the directory and what to do.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "support/temp_dir.hpp"
#include "sinew/core/error.hpp"
#include "sinew/model/checkpoint.hpp"
#include "sinew/model/solve_model.hpp"
#include "sinew/scene/load_scene.hpp"

namespace sinew::model {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

/// A 10 mm rubber cube fixed at the bottom; its top face is pushed down `push` mm and turned
/// `turn_deg` about the vertical axis through `pivot`, in `increments` increments.
json twisted_cube(double push, double turn_deg, const Vector3& pivot, int increments) {
  json scene = json::parse(R"({
    "name": "twisted-cube", "units": "mm, N, MPa",
    "materials": {"rubber": {"law": "mooney-rivlin", "C1": 0.5, "C2": 0.1, "a": 2.0}},
    "bodies": [{"name": "block",
      "mesh": {"generate": {"element_size": 4.0,
        "parts": [{"region": "rubber", "shape": {"box": {"min": [0, 0, 0], "max": [10, 10, 10]}}}]}},
      "regions": {"rubber": {"material": "rubber"}}}],
    "boundary_conditions": [
      {"name": "bottom", "type": "fixed", "nodes": {"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}}},
      {"name": "top", "type": "prescribed", "nodes": {"plane": {"point": [0, 0, 10], "normal": [0, 0, 1]}}}
    ],
    "solver": {"newton": {"residual_tolerance": 1e-10}}
  })");
  scene["boundary_conditions"][1]["motion"] = {
      {"pivot", {pivot.x(), pivot.y(), pivot.z()}},
      {"keyframes",
       {{{"lambda", 0}},
        {{"lambda", 1},
         {"translation", {0, 0, -push}},
         {"rotation", {{"axis", {0, 0, 1}}, {"angle_deg", turn_deg}}}}}}};
  scene["solver"]["increments"] = increments;
  return scene;
}

/// Runs `scene` and writes its checkpoint into `directory` as `sinew run` does (the last accepted
/// step; finished when the run succeeded, unless `stopped`). Returns the result.
solver::StepperResult run_into(const json& scene, const std::string& base, const std::string& directory,
                               bool stopped = false) {
  Model model = build_model(scene::parse_scene(scene, base));
  std::optional<RunSnapshot> last;
  solver::StepperCallbacks callbacks;
  callbacks.on_accepted = [&](const solver::StepperSnapshot& s) { last = take_snapshot(model, s); };
  solver::StepperResult result = solve_model(model, callbacks);
  std::filesystem::create_directories(directory);
  if (last) {
    Checkpoint checkpoint;
    checkpoint.fingerprint = model_fingerprint(model, scene.dump());
    checkpoint.mesh_fingerprint = mesh_fingerprint(model);
    checkpoint.finished = result.success && !stopped;
    checkpoint.snapshot = *last;
    write_checkpoint(directory + "/" + kCheckpointFile, checkpoint);
  }
  return result;
}

TEST(StageStart, TwoStaticStagesEndWhereOneRunEnds) {
  sinew::testing::TempDir dir("sinew-stage");
  const Vector3 pivot(5, 5, 10);
  const solver::StepperResult one = run_into(twisted_cube(2, 30, pivot, 4), "", dir.file("one"));
  ASSERT_TRUE(one.success) << one.message;
  ASSERT_TRUE(run_into(twisted_cube(1, 15, pivot, 2), "", dir.file("first")).success);
  // The second stage turns about the top's centre where the first stage left it.
  json second = twisted_cube(1, 15, pivot - Vector3(0, 0, 1), 2);
  second["initial_state"] = "first";
  Model model = build_model(scene::parse_scene(second, dir.path().string()));
  ASSERT_TRUE(model.dofs->has_start());
  const solver::StepperResult two = solve_model(model);
  ASSERT_TRUE(two.success) << two.message;
  const double size = 10;
  std::printf("[ stages   ] two static stages against one run: largest position difference %.3g mm\n",
              (two.last_state.x - one.last_state.x).cwiseAbs().maxCoeff());
  EXPECT_LT((two.last_state.x - one.last_state.x).cwiseAbs().maxCoeff(), 1e-7 * size);
  // The elements' reference is still the mesh: the displacement from rest is the whole way.
  const Positions& rest = model.problem->mesh.rest;
  EXPECT_NEAR((two.last_state.x - rest).col(2).minCoeff(), -2, 1e-9);
}

TEST(StageStart, ADynamicStageGoesOnWithTheVelocitiesItStartsWith) {
  // A free rubber cube falling under gravity, fixed steps of 0.01: 0.1 s, then 0.1 s more,
  // against 0.2 s in one run.
  auto falling = [](double end_time) {
    json scene = json::parse(R"({
      "name": "falling-cube", "units": "mm, N, MPa, s",
      "materials": {"rubber": {"law": "neo-hookean", "mu": 0.4, "lambda": 0.6}},
      "bodies": [{"name": "cube",
        "mesh": {"generate": {"element_size": 5.0,
          "parts": [{"region": "rubber", "shape": {"box": {"min": [0, 0, 0], "max": [10, 10, 10]}}}]}},
        "regions": {"rubber": {"material": "rubber", "density": 1e-9}}}],
      "loads": {"gravity": [0, 0, -9810]},
      "dynamics": {"integrator": "implicit-euler", "output_interval": 0.05, "time_step": 0.01,
                   "max_time_step": 0.01}
    })");
    scene["dynamics"]["end_time"] = end_time;
    return scene;
  };
  sinew::testing::TempDir dir("sinew-stage");
  const solver::StepperResult one = run_into(falling(0.2), "", dir.file("one"));
  ASSERT_TRUE(one.success) << one.message;
  const solver::StepperResult first = run_into(falling(0.1), "", dir.file("first"));
  ASSERT_TRUE(first.success) << first.message;
  json second = falling(0.1);
  second["initial_state"] = dir.file("first");
  Model model = build_model(scene::parse_scene(second, ""));
  ASSERT_EQ(model.start_velocity.rows(), model.problem->mesh.num_nodes());
  EXPECT_NEAR(model.start_velocity.col(2).mean(), -9810 * 0.1, 1e-6 * 981);
  const solver::StepperResult two = solve_model(model);
  ASSERT_TRUE(two.success) << two.message;
  // Free fall: 0.5 g t^2 = 196 mm by t = 0.2 (implicit Euler a little more); a stage that
  // started at rest would have fallen 49 + 49 mm instead.
  std::printf("[ stages   ] two dynamic stages against one run: largest position difference %.3g mm, fall %.2f mm\n",
              (two.last_state.x - one.last_state.x).cwiseAbs().maxCoeff(), -two.last_state.x.col(2).minCoeff());
  EXPECT_LT((two.last_state.x - one.last_state.x).cwiseAbs().maxCoeff(), 1e-9 * 200);
  EXPECT_LT(two.last_state.x.col(2).minCoeff(), -190);
  // A quasistatic stage does not take velocities.
  json quasistatic = second;
  quasistatic["dynamics"]["integrator"] = "quasistatic";
  quasistatic["dynamics"]["mass_damping"] = 10.0;
  quasistatic["boundary_conditions"] = json::array(
      {{{"name", "base"}, {"type", "fixed"}, {"nodes", {{"plane", {{"point", {0, 0, 0}}, {"normal", {0, 0, 1}}}}}}}});
  EXPECT_EQ(build_model(scene::parse_scene(quasistatic, "")).start_velocity.rows(), 0);
}

TEST(StageStart, ARigidBodyStartsFromThePoseTheEarlierStageLeftItIn) {
  // A rigid plate pressed 1 mm into a rubber block (prescribed), then held (fixed) while the
  // block's top... stays: the second stage's plate must not jump back to its rest place.
  auto pressed = [](bool move) {
    json scene = json::parse(R"({
      "name": "plate", "units": "mm, N, MPa",
      "materials": {"rubber": {"law": "neo-hookean", "mu": 0.4, "lambda": 0.6}},
      "bodies": [{"name": "block",
        "mesh": {"generate": {"element_size": 4.0, "parts": [
          {"region": "rubber", "shape": {"box": {"min": [0, 0, 0], "max": [10, 10, 8]}}},
          {"region": "plate", "shape": {"box": {"min": [0, 0, 8], "max": [10, 10, 10]}}}]}},
        "regions": {"rubber": {"material": "rubber"}, "plate": {"rigid": "fixed"}}}],
      "boundary_conditions": [
        {"name": "bottom", "type": "fixed", "nodes": {"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}}}],
      "solver": {"increments": 2}
    })");
    if (move)
      scene["bodies"][0]["regions"]["plate"]["rigid"] = {
          {"prescribed",
            {{"translation", {0, 0, -1}}, {"rotation", {{"axis", {1, 0, 0}}, {"point", {5, 5, 9}}, {"angle_deg", 5}}}}}};
    return scene;
  };
  sinew::testing::TempDir dir("sinew-stage");
  const solver::StepperResult first = run_into(pressed(true), "", dir.file("first"));
  ASSERT_TRUE(first.success) << first.message;
  json held = pressed(false);
  held["initial_state"] = dir.file("first");
  Model model = build_model(scene::parse_scene(held, ""));
  const solver::StepperResult second = solve_model(model);
  ASSERT_TRUE(second.success) << second.message;
  // Nothing changed in the second stage: the block stays pressed, in equilibrium already.
  EXPECT_LT((second.last_state.x - first.last_state.x).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_NEAR((second.last_state.x - model.problem->mesh.rest).col(2).minCoeff(), -1 - 5 * 0.0873, 0.1);
}

TEST(StageStart, RefusesAStartItCannotUse) {
  sinew::testing::TempDir dir("sinew-stage");
  const Vector3 pivot(5, 5, 10);
  auto refused = [&](const std::string& initial_state, json scene = json()) {
    if (scene.is_null()) scene = twisted_cube(1, 15, pivot, 1);
    scene["initial_state"] = initial_state;
    try {
      build_model(scene::parse_scene(scene, dir.path().string()));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_THAT(refused("nowhere"), HasSubstr("no such directory"));
  std::filesystem::create_directories(dir.file("empty"));
  EXPECT_THAT(refused("empty"), HasSubstr("holds no checkpoint.cbor"));
  // A run that stopped (interrupted, or failed after its first step).
  ASSERT_TRUE(run_into(twisted_cube(1, 15, pivot, 1), "", dir.file("stopped"), true).success);
  EXPECT_THAT(refused("stopped"), HasSubstr("did not finish (it stopped at lambda = 1)"));
  // Another mesh.
  json coarse = twisted_cube(1, 15, pivot, 1);
  coarse["bodies"][0]["mesh"]["generate"]["element_size"] = 5.0;
  ASSERT_TRUE(run_into(coarse, "", dir.file("coarse")).success);
  EXPECT_THAT(refused("coarse"), HasSubstr("other meshes"));
  // A damaged checkpoint.
  std::filesystem::create_directories(dir.file("damaged"));
  { std::ofstream(dir.file("damaged") + "/checkpoint.cbor") << "not cbor"; }
  EXPECT_THAT(refused("damaged"), HasSubstr("not a usable sinew checkpoint"));
  // The message names the directory.
  EXPECT_THAT(refused("coarse"), HasSubstr(dir.file("coarse")));
}

}  // namespace
}  // namespace sinew::model
