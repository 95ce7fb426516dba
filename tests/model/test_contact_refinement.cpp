/// @file test_contact_refinement.cpp
/// The augmented Lagrangian's outer iteration (model/contact_refinement.hpp) when a re-solve
/// fails: retry_softer() offers half, a quarter and an eighth of the last multiplier update, then
/// restores the pressures before it and ends the updates of the step until the next one; its
/// warning names what failed (a multiplier update with the penetration left and the tolerance, or
/// a friction refresh, which has no penetration tolerance).

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <sstream>
#include <string>

#include "support/captured_log.hpp"
#include "sinew/model/contact_refinement.hpp"
#include "sinew/model/model.hpp"
#include "sinew/scene/load_scene.hpp"

namespace sinew::model {
namespace {

/// The nodal pressures of `contact`, #V (zeros where it has none yet).
VectorX pressures(const contact::ContactEnergy& contact, Index num_nodes) {
  return contact.pressure().size() == 0 ? VectorX::Zero(num_nodes) : contact.pressure();
}

using sinew::testing::CapturedLog;

/// The upper block of stacked-blocks pushed 0.1 mm into the lower one.
fem::State pressed_blocks(const Model& model) {
  fem::State state = model.dofs->initial_state(0.0);
  const fem::BodyRange& upper = model.problem->bodies.at(1);
  state.x.middleRows(upper.first_node, upper.num_nodes).col(2).array() -= 0.1;
  return state;
}

TEST(ContactRefinement, AFailedReSolveIsOfferedHalfAQuarterAndAnEighthOfTheUpdateThenNothing) {
  scene::SceneConfig config = scene::load_scene_file(std::string(SINEW_SOURCE_DIR) + "/examples/stacked-blocks.json");
  config.contact.enforcement.method = contact::ContactEnforcement::AugmentedLagrangian;
  config.contact.enforcement.penetration_tolerance = 1e-3;
  config.contact.relative_penetration_tolerance.reset();
  Model model = build_model(config);
  ASSERT_TRUE(model.contact);
  const Index n = model.problem->mesh.num_nodes();
  const fem::State state = pressed_blocks(model);

  ContactRefinement refinement(*model.contact, model.contact_enforcement);
  ASSERT_TRUE(refinement.refine(state));
  const VectorX update = pressures(*model.contact, n);
  ASSERT_GT(update.maxCoeff(), 0);
  for (double fraction : {0.5, 0.25, 0.125}) {
    ASSERT_TRUE(refinement.retry_softer()) << fraction;
    EXPECT_LT((pressures(*model.contact, n) - fraction * update).cwiseAbs().maxCoeff(), 1e-12 * update.maxCoeff())
        << fraction;
  }
  // Nothing smaller: the pressures before the update (none), and no more updates in this step.
  {
    const CapturedLog log;
    EXPECT_FALSE(refinement.retry_softer());
    EXPECT_NE(log.text().find("no convergence after the multiplier update of this step"), std::string::npos)
        << log.text();
    EXPECT_NE(log.text().find("tolerance 0.001"), std::string::npos) << log.text();
  }
  EXPECT_EQ(pressures(*model.contact, n).cwiseAbs().maxCoeff(), 0);
  EXPECT_FALSE(refinement.refine(state));
  // The next step updates again.
  refinement.accept(state);
  EXPECT_TRUE(refinement.refine(state));
  EXPECT_LT((pressures(*model.contact, n) - update).cwiseAbs().maxCoeff(), 1e-12 * update.maxCoeff());
}

TEST(ContactRefinement, AFailedReSolveAfterAFrictionRefreshIsNotRetriedAndSaysSoWithoutATolerance) {
  scene::SceneConfig config = scene::load_scene_file(std::string(SINEW_SOURCE_DIR) + "/examples/stacked-blocks.json");
  config.contact.friction.coefficient = 0.5;
  Model model = build_model(config);
  ASSERT_TRUE(model.contact);
  ASSERT_TRUE(model.friction);
  const fem::State state = pressed_blocks(model);
  ContactRefinement refinement(*model.contact, model.contact_enforcement, model.friction.get());
  // The friction was lagged at rest (no normal force): pressed, the normal force changed.
  ASSERT_TRUE(refinement.refine(state));
  const CapturedLog log;
  EXPECT_FALSE(refinement.retry_softer());
  EXPECT_NE(log.text().find("no convergence after the friction refresh of this step"), std::string::npos)
      << log.text();
  EXPECT_EQ(log.text().find("tolerance"), std::string::npos) << "friction has no penetration tolerance: " << log.text();
}

}  // namespace
}  // namespace sinew::model
