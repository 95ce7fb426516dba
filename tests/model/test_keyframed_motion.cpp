/// @file test_keyframed_motion.cpp
/// Keyframed prescribed motion (fem/motion.hpp) through a whole solve: prescribed nodes follow
/// their keyframes exactly at every increment, and a prescribed rigid body turned 160 degrees
/// by keyframes is taken in as many steps as the per-step turn bound needs.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sinew/model/solve_model.hpp"
#include "sinew/scene/load_scene.hpp"

namespace sinew::model {
namespace {

using nlohmann::json;

/// A 10 mm rubber cube, fixed at the bottom; its top face goes up 2 mm by lambda = 0.5 and back
/// down to 1 mm by lambda = 1, turning 20 degrees about the cube's vertical axis on the way.
json keyframed_block() {
  return json::parse(R"({
    "name": "keyframed-block", "units": "mm, N, MPa",
    "materials": {"rubber": {"law": "mooney-rivlin", "C1": 0.5, "C2": 0.1, "a": 2.0}},
    "bodies": [{"name": "block",
      "mesh": {"generate": {"element_size": 5.0,
        "parts": [{"region": "rubber", "shape": {"box": {"min": [0, 0, 0], "max": [10, 10, 10]}}}]}},
      "regions": {"rubber": {"material": "rubber"}}}],
    "boundary_conditions": [
      {"name": "bottom", "type": "fixed", "nodes": {"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}}},
      {"name": "top", "type": "prescribed", "nodes": {"plane": {"point": [0, 0, 10], "normal": [0, 0, 1]}},
       "motion": {"pivot": [5, 5, 10], "keyframes": [
         {"lambda": 0},
         {"lambda": 0.5, "translation": [0, 0, 2], "rotation": {"axis": [0, 0, 1], "angle_deg": 10}},
         {"lambda": 1, "translation": [0, 0, 1], "rotation": {"axis": [0, 0, 1], "angle_deg": 20}}]}}
    ],
    "solver": {"increments": 4}
  })");
}

TEST(KeyframedMotion, PrescribedNodesFollowTheirKeyframesAtEveryIncrement) {
  const scene::SceneConfig config = scene::parse_scene(keyframed_block(), "");
  Model model = build_model(config);
  const fem::RigidMotion& motion = config.boundary_conditions.at(1).motion;
  const Positions& rest = model.problem->mesh.rest;
  std::vector<double> lambdas;
  solver::StepperCallbacks callbacks;
  callbacks.on_segment = [&](int k, const solver::StepRecord&, const fem::State& state, const NodalVectors&) {
    if (k == 0) return;
    lambdas.push_back(state.lambda);
    int top = 0;
    for (Index v = 0; v < rest.rows(); ++v) {
      if (std::abs(rest(v, 2) - 10) > 1e-9) continue;
      ++top;
      const Vector3 expected = motion.apply(rest.row(v).transpose(), state.lambda);
      EXPECT_NEAR((state.x.row(v).transpose() - expected).norm(), 0, 1e-10) << "node " << v << " at " << state.lambda;
    }
    EXPECT_GT(top, 4);
  };
  const solver::StepperResult result = solve_model(model, callbacks);
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_EQ(lambdas, (std::vector<double>{0.25, 0.5, 0.75, 1.0}));
  // The top centre went up 2 and came back to 1.
  const Vector3 centre = motion.apply(Vector3(5, 5, 10), 1.0);
  EXPECT_NEAR((centre - Vector3(5, 5, 11)).norm(), 0, 1e-12);
}

TEST(KeyframedMotion, ALargeKeyframedTurnOfARigidBodyIsSplitIntoBoundedSteps) {
  // A rigid bar turned 160 degrees in one increment: the stepper bounds each step's turn.
  json scene = json::parse(R"({
    "name": "turned-bar", "units": "mm, N, MPa",
    "materials": {},
    "bodies": [{"name": "bar",
      "mesh": {"generate": {"element_size": 2.0,
        "parts": [{"region": "steel", "shape": {"box": {"min": [0, 0, 0], "max": [10, 2, 2]}}}]}},
      "regions": {"steel": {"rigid": {"prescribed": {"pivot": [0, 1, 1], "keyframes": [
        {"lambda": 0}, {"lambda": 1, "rotation": {"axis": [0, 0, 1], "angle_deg": 160}}]}}}}}],
    "solver": {"increments": 1}
  })");
  Model model = build_model(scene::parse_scene(scene, ""));
  int steps = 0;
  solver::StepperCallbacks callbacks;
  callbacks.on_step = [&](const solver::StepRecord&, const fem::State&, const NodalVectors&) { ++steps; };
  const solver::StepperResult result = solve_model(model, callbacks);
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_GT(steps, 1);
  ASSERT_EQ(result.last_state.rigid.size(), 1u);
  EXPECT_NEAR(Eigen::AngleAxisd(result.last_state.rigid[0].R).angle(), 160 * M_PI / 180, 1e-12);
  // The far end of the bar swept round the pivot.
  const Vector3 end = result.last_state.rigid[0].R * (Vector3(10, 1, 1) - model.dofs->rigid_center(0)) +
                      model.dofs->rigid_center(0) + result.last_state.rigid[0].t;
  const double a = 160 * M_PI / 180;
  EXPECT_NEAR((end - Vector3(10 * std::cos(a), 1 + 10 * std::sin(a), 1)).norm(), 0, 1e-9);
}

}  // namespace
}  // namespace sinew::model
