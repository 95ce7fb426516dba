/// @file test_contact_examples.cpp
/// The contact examples as regression tests (issue 3): Hertz, the contact patch test, self-contact
/// of a pinched tube, and the dissertation's pointed body in a concave corner.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "examples/example_support.hpp"

namespace sinew::examples_test {
namespace {

// hertz-ball: quarter hemisphere (R = 10 mm, E = 1 MPa, nu = 0.3) pressed d = 0.5 lambda mm on a
// rigid block. Hertz: F = 4/3 E/(1 - nu^2) sqrt(R) d^1.5 (whole sphere; the model is a quarter).
TEST(ContactExamples, HertzBallFollowsHertzLawForSmallIndentation) {
  TempDir directory;
  const ExampleRun run = run_example("hertz-ball", directory);
  expect_complete_outputs(run);
  ASSERT_TRUE(run.report.success) << run.report.message;
  const auto steps = read_csv(run.output / "steps.csv");
  ASSERT_EQ(steps.rows.size(), 5u);
  const double E_star = 1.0 / (1 - 0.3 * 0.3), R = 10;
  std::vector<double> d, F;
  for (std::size_t i = 0; i < steps.rows.size(); ++i) {
    d.push_back(0.5 * steps.at(i, "lambda"));
    F.push_back(-4 * steps.at(i, "top.fz"));
    const double hertz = 4.0 / 3.0 * E_star * std::sqrt(R) * std::pow(d.back(), 1.5);
    std::printf("[ example  ] hertz-ball: d %.2f mm  F %.5f N  Hertz %.5f N  ratio %.4f  max penetration %.5f mm\n",
                d.back(), F.back(), hertz, F.back() / hertz, steps.at(i, "max_penetration"));
    // Linear tets with 4-6 elements across the contact are stiff: within +20 %, never softer than -5 %.
    EXPECT_GT(F.back() / hertz, 0.95) << "step " << i + 1;
    EXPECT_LT(F.back() / hertz, 1.20) << "step " << i + 1;
    // The block carries what the top pushes; the contact force is the same force.
    EXPECT_NEAR(steps.at(i, "block/block.fz"), -steps.at(i, "top.fz"), 1e-6 * F.back());
    EXPECT_NEAR(steps.at(i, "contact.ball.block.fz"), -steps.at(i, "top.fz"), 1e-6 * F.back());
    // Penetration stays a few per cent of the indentation.
    EXPECT_LT(steps.at(i, "max_penetration"), 0.08 * d.back());
    EXPECT_LE(steps.at(i, "newton_iterations"), 8) << "Newton should converge quadratically";
  }
  const double exponent = std::log(F.back() / F.front()) / std::log(d.back() / d.front());
  std::printf("[ example  ] hertz-ball: force exponent %.4f (Hertz 1.5)\n", exponent);
  EXPECT_NEAR(exponent, 1.5, 0.06);
  constexpr double kRecordedTopForce = -0.4703569;  // N, quarter model, d = 0.5 mm
  EXPECT_NEAR(steps.at(4, "top.fz"), kRecordedTopForce, 2e-3 * std::abs(kRecordedTopForce));
  // The collision phase (broad and narrow phase) is timed on its own, inside the run's wall time.
  const auto& times = run.report.result.times;
  EXPECT_GT(times.collision, 0);
  EXPECT_LE(times.total(), run.report.wall_seconds);
}

// stacked-blocks: the contact patch test with non-matching meshes.
TEST(ContactExamples, StackedBlocksPassTheContactPatchTest) {
  TempDir directory;
  const ExampleRun run = run_example("stacked-blocks", directory);
  expect_complete_outputs(run);
  ASSERT_TRUE(run.report.success) << run.report.message;
  const auto steps = read_csv(run.output / "steps.csv");
  for (std::size_t i = 0; i < steps.rows.size(); ++i) {
    const double load = -steps.at(i, "top.fz");
    EXPECT_GT(load, 0);
    // Reaction below = applied load above = force through the interface.
    EXPECT_NEAR(steps.at(i, "bottom.fz"), load, 1e-8 * load);
    EXPECT_NEAR(steps.at(i, "contact.lower.upper.fz"), -load, 1e-8 * load);
    // Uniform pressure: the penetration is the same everywhere on the interface.
    EXPECT_LT(steps.at(i, "max_penetration"), 1.02 * steps.at(i, "mean_penetration")) << "step " << i + 1;
  }
  // The interface stays flat: every node that started on it moved down by the same amount.
  const auto pvd = read_pvd(run.output / "sinew.pvd");
  const VtuState state = read_vtu_state(run.output / pvd.back().file);
  const Eigen::MatrixXd X = state.rest();
  double lowest = 1e300, highest = -1e300;
  for (Eigen::Index v = 0; v < X.rows(); ++v)
    if (std::abs(X(v, 2) - 5.0) < 1e-6) {
      lowest = std::min(lowest, state.u(v, 2));
      highest = std::max(highest, state.u(v, 2));
    }
  std::printf("[ example  ] stacked-blocks: load %.6f N, interface uz in [%.6f, %.6f] mm, penetration %.6f mm\n",
              -steps.at(3, "top.fz"), lowest, highest, steps.at(3, "max_penetration"));
  EXPECT_LT(highest - lowest, 0.02 * std::abs(lowest));
  constexpr double kRecordedLoad = 5.168784;  // N
  EXPECT_NEAR(-steps.at(3, "top.fz"), kRecordedLoad, 1e-4 * kRecordedLoad);
}

// pinched-tube: two rigid plates pinch a clamped tube until its inner wall touches itself.
TEST(ContactExamples, PinchedTubeTouchesItselfAndBalances) {
  TempDir directory;
  const ExampleRun run = run_example("pinched-tube", directory);
  expect_complete_outputs(run);
  ASSERT_TRUE(run.report.success) << run.report.message;
  const auto steps = read_csv(run.output / "steps.csv");
  const std::size_t last = steps.rows.size() - 1;
  for (std::size_t i = 0; i < steps.rows.size(); ++i) {
    // The plates push; the contact force on the tube from a plate is that plate's reaction.
    EXPECT_LT(steps.at(i, "upper_plate/plate.fz"), 0);
    EXPECT_GT(steps.at(i, "lower_plate/plate.fz"), 0);
    EXPECT_NEAR(steps.at(i, "contact.tube.upper_plate.fz"), steps.at(i, "upper_plate/plate.fz"),
                1e-6 * std::abs(steps.at(i, "upper_plate/plate.fz")));
    EXPECT_NEAR(steps.at(i, "contact.tube.lower_plate.fz"), steps.at(i, "lower_plate/plate.fz"),
                1e-6 * std::abs(steps.at(i, "lower_plate/plate.fz")));
  }
  // No self-contact while the tube is open, self-contact at the end.
  EXPECT_EQ(steps.at(0, "contact.tube.tube.force"), 0.0);
  EXPECT_GT(steps.at(last, "contact.tube.tube.force"), 1.0);
  std::printf("[ example  ] pinched-tube: plates %.5f / %.5f N, self-contact force %.5f N, max penetration %.4f mm\n",
              steps.at(last, "upper_plate/plate.fz"), steps.at(last, "lower_plate/plate.fz"),
              steps.at(last, "contact.tube.tube.force"), steps.at(last, "max_penetration"));
  // Penetration stays below half the wall (1.5 mm), where material depth would push the wrong way.
  EXPECT_LT(steps.at(last, "max_penetration"), 0.6);
  // rigid_bodies.csv: the plates' reference points (the mean of their nodes at rest, near the
  // plates' centres) follow the prescribed translation, unrotated.
  const auto rigid = read_csv(run.output / "rigid_bodies.csv");
  ASSERT_EQ(rigid.rows.size(), steps.rows.size());
  const double upper_z = rigid.at(0, "upper_plate/plate.z") + 3.9 * rigid.at(0, "lambda");
  const double upper_x = rigid.at(0, "upper_plate/plate.x");
  EXPECT_NEAR(upper_z, 6.0, 0.1);
  EXPECT_NEAR(upper_x, 6.0, 0.1);
  for (std::size_t i = 0; i < rigid.rows.size(); ++i) {
    const double lambda = rigid.at(i, "lambda");
    EXPECT_EQ(rigid.at(i, "step"), steps.at(i, "step"));
    EXPECT_NEAR(rigid.at(i, "upper_plate/plate.z"), upper_z - 3.9 * lambda, 1e-9) << "row " << i;
    EXPECT_NEAR(rigid.at(i, "upper_plate/plate.x"), upper_x, 1e-9) << "row " << i;
    EXPECT_EQ(rigid.at(i, "upper_plate/plate.angle_deg"), 0.0);
  }
  constexpr double kRecordedUpperPlate = -12.9884;  // N
  EXPECT_NEAR(steps.at(last, "upper_plate/plate.fz"), kRecordedUpperPlate, 2e-3 * std::abs(kRecordedUpperPlate));
}

// corner-wedge: the dissertation's Fig. 25 pair, starting 0.5 mm interpenetrated.
TEST(ContactExamples, CornerWedgeSeparatesFromDeepPenetrationAndConverges) {
  TempDir directory;
  const ExampleRun run = run_example("corner-wedge", directory);
  expect_complete_outputs(run);
  ASSERT_TRUE(run.report.success) << run.report.message;
  const auto steps = read_csv(run.output / "steps.csv");
  const std::size_t last = steps.rows.size() - 1;
  for (std::size_t i = 0; i < steps.rows.size(); ++i) {
    // Wedge: pushed by its prescribed face, held by contact. Corner: held by its base.
    for (const char* c : {"x", "z"}) {
      const std::string push = std::string("push.f") + c, contact = std::string("contact.corner.wedge.f") + c,
                        base = std::string("base.f") + c;
      EXPECT_NEAR(steps.at(i, contact), steps.at(i, push), 1e-6 * std::abs(steps.at(i, push)));
      EXPECT_NEAR(steps.at(i, base), -steps.at(i, push), 1e-6 * std::abs(steps.at(i, push)));
    }
    EXPECT_LE(steps.at(i, "newton_iterations"), 8) << "step " << i + 1;
  }
  // Pushed diagonally into the corner: both components push the corner away from the wedge.
  EXPECT_GT(steps.at(last, "base.fx"), 0);
  EXPECT_GT(steps.at(last, "base.fz"), 0);
  std::printf("[ example  ] corner-wedge: base force (%.5f, %.5f) N, max penetration %.4f mm, mean %.5f mm\n",
              steps.at(last, "base.fx"), steps.at(last, "base.fz"), steps.at(last, "max_penetration"),
              steps.at(last, "mean_penetration"));
  EXPECT_LT(steps.at(last, "max_penetration"), 0.25);
  constexpr double kRecordedBaseFz = 5.429519;  // N
  EXPECT_NEAR(steps.at(last, "base.fz"), kRecordedBaseFz, 2e-3 * kRecordedBaseFz);
}

}  // namespace
}  // namespace sinew::examples_test
