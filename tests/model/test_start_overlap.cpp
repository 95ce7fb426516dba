/// @file test_start_overlap.cpp
/// Parts that overlap at the start (docs/contact.md, "Parts that overlap at the start"): the
/// model names each overlapping pair of bodies with its depth and place; contact leaves out the
/// pairs neither side of which can move, so such an overlap changes neither the solution nor
/// Newton's convergence test; parts that only touch are not reported.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "scene/scene_test_support.hpp"
#include "sinew/model/solve_model.hpp"
#include "sinew/scene/load_scene.hpp"
#include "support/captured_log.hpp"
#include "support/contact_scenes.hpp"

namespace sinew::model {
namespace {

using nlohmann::json;
using sinew::testing::CapturedLog;
using ::testing::HasSubstr;
using ::testing::Not;

Model model_of(const json& scene) { return build_model(scene::parse_scene(scene, "")); }

/// The pressed box on its plate, plus a soft pad held fixed in every node, away from the box
/// and sunk `sink` into the plate, with a penalty 780 times the automatic one between
/// pad and plate (so that their overlap's forces dwarf the box's).
json scene_with_fixed_pad(double sink) {
  json scene = sinew::testing::pressed_box_on_plate_scene();
  scene["solver"]["increments"] = 2;
  scene["bodies"].push_back(json::parse(R"({"name": "pad",
      "mesh": {"generate": {"element_size": 0.25, "parts": [
        {"region": "gel", "shape": {"box": {"min": [1.4, 0, 0], "max": [1.9, 1, 0.5]}}}]}},
      "regions": {"gel": {"material": "gel"}}})"));
  scene["bodies"].back()["transform"] = {{"translate", {0.0, 0.0, -sink}}};
  scene["boundary_conditions"].push_back(json::parse(R"({"name": "pad", "type": "fixed", "nodes": {"body": "pad", "all": true}})"));
  scene["contact"]["pairs"] = json::parse(R"([{"bodies": ["plate", "pad"], "penalty": 1e5}])");
  return scene;
}

TEST(StartOverlap, PartsThatCannotMoveAreNamedAndLeftOutOfContact) {
  CapturedLog log;
  Model model = model_of(scene_with_fixed_pad(0.4));
  EXPECT_THAT(log.text(), HasSubstr("contact at the start: \"plate\" and \"pad\" overlap by up to"));
  EXPECT_THAT(log.text(), HasSubstr("where neither side can move (fixed or prescribed); those pairs are left out of contact"));
  EXPECT_THAT(log.text(), Not(HasSubstr("\"box\" and")));
  const Positions x = model.dofs->initial_state(0.0).x;
  model.contact->update(x);
  EXPECT_EQ(model.contact->value(x), 0.0);
}

// Against the same pad placed on the plate without overlap: the same Newton iterations and the
// same box. Counted in contact, the overlap's constant forces would widen the force scale of
// Newton's convergence test (the largest term's force norm) and end the iterations early.
TEST(StartOverlap, AnOverlapOfPartsThatCannotMoveChangesNeitherTheSolutionNorNewton) {
  Model sunk = model_of(scene_with_fixed_pad(0.4));
  Model resting = model_of(scene_with_fixed_pad(0.0));
  const solver::StepperResult a = solve_model(sunk);
  const solver::StepperResult b = solve_model(resting);
  ASSERT_TRUE(a.success) << a.message;
  ASSERT_TRUE(b.success) << b.message;
  EXPECT_EQ(a.newton_iterations, b.newton_iterations);
  const fem::BodyRange& box = sunk.problem->bodies.at(0);
  const NodalVectors xa = a.last_state.x.middleRows(box.first_node, box.num_nodes);
  const NodalVectors xb = b.last_state.x.middleRows(box.first_node, box.num_nodes);
  EXPECT_LT((xa - xb).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(StartOverlap, PartsThatCanMoveAreNamedAndPartsThatOnlyTouchAreNot) {
  {
    CapturedLog log;
    model_of(sinew::testing::box_on_plate_scene());  // the box's bottom lies on the plate's top
    EXPECT_THAT(log.text(), Not(HasSubstr("contact at the start")));
  }
  json scene = sinew::testing::box_on_plate_scene();
  scene["bodies"][0]["transform"] = {{"translate", {0.0, 0.0, -0.05}}};
  CapturedLog log;
  model_of(scene);
  EXPECT_THAT(log.text(), HasSubstr("contact at the start: \"box\" and \"plate\" overlap by up to"));
  EXPECT_THAT(log.text(), HasSubstr("contact pushes them apart in the first step"));
  EXPECT_THAT(log.text(), Not(HasSubstr("left out of contact")));
}

// Six unit boxes 0.1 apart, each overlapping all the others: 15 overlapping pairs, the 10 deepest named.
TEST(StartOverlap, ManyOverlapsAreCountedAndOnlyTheDeepestNamed) {
  json scene = json::parse(R"({"units": "m, N, Pa",
      "materials": {"gel": {"law": "neo-hookean", "mu": 1.0, "lambda": 10.0}}, "bodies": [], "contact": {}})");
  for (int b = 0; b < 6; ++b) {
    const double shift = 0.1 * b;
    json body = json::parse(R"({"mesh": {"generate": {"element_size": 0.5, "parts": [
        {"region": "gel", "shape": {"box": {"min": [0, 0, 0], "max": [1, 1, 1]}}}]}},
        "regions": {"gel": {"material": "gel"}}})");
    body["name"] = fmt::format("box{}", b);
    body["transform"] = {{"translate", {shift, 0.0, 0.0}}};
    scene["bodies"].push_back(body);
  }
  CapturedLog log;
  model_of(scene);
  const std::string text = log.text();
  EXPECT_THAT(text, HasSubstr("contact at the start: 15 overlaps of pairs of bodies; the 10 deepest follow"));
  // Ten named, deepest first (material depth: a box's is at most 0.5, at its centre).
  std::vector<double> depths;
  const std::string marker = "\" overlap by up to ";
  for (std::size_t at = text.find(marker); at != std::string::npos; at = text.find(marker, at + 1))
    depths.push_back(std::stod(text.substr(at + marker.size())));
  ASSERT_EQ(depths.size(), 10u);
  EXPECT_TRUE(std::is_sorted(depths.rbegin(), depths.rend())) << text;
  EXPECT_GT(depths.back(), 0.0);
  EXPECT_LE(depths.front(), 0.5 + 1e-9);
}

}  // namespace
}  // namespace sinew::model
