/// @file test_snake_examples.cpp
/// The dissertation's coiling snake (Fig. 49, examples/coiling-snake.json from
/// scripts/make_coiling_snake.py): the head, moved by keyframes toward the fixed tail while it
/// turns, coils the rod into a loop that closes on itself; self-contact keeps it from passing
/// through, no element inverts, and the rod is in equilibrium between its two ends. The snake
/// and the apple (Fig. 50, examples/snake-apple.json from scripts/make_snake_apple.py): a rigid
/// apple guided by keyframes into the mouth of a tube fixed at its head and along a zigzag to its
/// tail; the tube bulges round it, its belly slides sideways on the ground plane, nothing passes
/// through the wall and the forces balance.

#include <gtest/gtest.h>

#include <cstdio>
#include <utility>

#include <fmt/format.h>

#include "examples/example_support.hpp"

namespace sinew::examples_test {
namespace {

TEST(SnakeExamples, CoilingSnakeClosesItsLoopOnItselfWithoutPassingThrough) {
#ifdef SINEW_SANITIZER_BUILD
  GTEST_SKIP() << "93 load steps with self-contact take minutes instrumented; the Release suite runs it";
#endif
  TempDir directory;
  const ExampleRun run = run_example("coiling-snake", directory);
  expect_complete_outputs(run);
  ASSERT_TRUE(run.report.success) << run.report.message;
  const auto steps = read_csv(run.output / "steps.csv");
  const std::size_t last = steps.rows.size() - 1;
  double deepest = 0;
  for (std::size_t i = 0; i < steps.rows.size(); ++i) {
    // Nothing but the two ends holds the rod: what the head takes, the tail gives (to the
    // Newton tolerance, about 1e-6 N per node here).
    for (const char* c : {"fx", "fy", "fz"}) {
      const double tail = steps.at(i, std::string("tail.") + c), head = steps.at(i, std::string("head.") + c);
      EXPECT_NEAR(tail, -head, 1e-4 + 1e-3 * std::abs(head)) << c << " at step " << i + 1;
    }
    deepest = std::max(deepest, steps.at(i, "max_penetration"));
    if (steps.at(i, "lambda") <= 0.5) {
      EXPECT_EQ(steps.at(i, "contact_pairs"), 0) << "touching while still a bend";
    }
  }
  // The loop has closed on itself at the end, with a force of its own.
  EXPECT_GT(steps.at(last, "contact_pairs"), 20);
  EXPECT_GT(steps.at(last, "contact.snake.snake.force"), 0.05);
  // Without passing through: below 5 % of the radius (4 mm) at every step (0.115 mm measured).
  EXPECT_LT(deepest, 0.2);
  // No element inverted in the last state.
  const std::string xml = read_text(run.output / "vtu" / "increment_0048.vtu");
  EXPECT_GT(vtu_array(xml, "J").minCoeff(), 0.05);
  std::printf("[ example  ] coiling-snake: %zu steps, %d contact pairs, self-contact force %.4f N, deepest %.4f mm, "
              "min J %.3f\n",
              steps.rows.size(), static_cast<int>(steps.at(last, "contact_pairs")),
              steps.at(last, "contact.snake.snake.force"), deepest, vtu_array(xml, "J").minCoeff());
}

TEST(SnakeExamples, AppleTravelsToTheTailInsideTheBulgingSnake) {
#ifdef SINEW_SANITIZER_BUILD
  GTEST_SKIP() << "30 load steps with 500 contact pairs take minutes instrumented; the Release suite runs it";
#endif
  TempDir directory;
  const ExampleRun run = run_example("snake-apple", directory);
  expect_complete_outputs(run);
  ASSERT_TRUE(run.report.success) << run.report.message;
  const auto steps = read_csv(run.output / "steps.csv");
  EXPECT_LE(steps.rows.size(), 45u);  // 30 measured, no cut
  double deepest = 0;
  for (std::size_t i = 0; i < steps.rows.size(); ++i) {
    // The snake is held by its head and the ground only: they take what the apple pushes.
    for (const char* c : {"fx", "fy", "fz"}) {
      const double contact = steps.at(i, std::string("contact.snake.apple.") + c);
      const double held = steps.at(i, std::string("head.") + c) + steps.at(i, std::string("belly.") + c);
      EXPECT_NEAR(held + contact, 0, 1e-4 + 1e-3 * std::abs(contact)) << c << " at step " << i + 1;
    }
    // The ground holds the belly in its plane only.
    EXPECT_EQ(steps.at(i, "belly.fx"), 0);
    EXPECT_EQ(steps.at(i, "belly.fy"), 0);
    deepest = std::max(deepest, steps.at(i, "max_penetration"));
    EXPECT_EQ(steps.at(i, "contact.snake.snake.force"), 0) << "step " << i + 1;
    if (steps.at(i, "lambda") >= 0.16) {
      // Inside the snake the apple is always held by the bore (it would lose contact, or its
      // force, if it slipped through the wall).
      EXPECT_GT(steps.at(i, "contact_pairs"), 300) << "step " << i + 1;
      EXPECT_GT(steps.at(i, "contact.snake.apple.fz"), 5) << "step " << i + 1;
    }
  }
  EXPECT_EQ(steps.at(0, "contact_pairs"), 0);  // in front of the mouth
  // Never through the wall: 0.30 mm measured, the thinnest wall is 3.5 mm.
  EXPECT_LT(deepest, 0.5);

  // The apple ends near the tail (its front 1.8 mm from the shortened tube's end, measured).
  const auto bodies = read_csv_columns(run.output / "rigid_bodies.csv", {"apple/apple.x", "apple/apple.y"});
  const double apple_x = bodies.rows.back().at(0);
  EXPECT_NEAR(apple_x, 126.0, 0.5);
  const double apple_radius = 9.8;
  const VtuState end = read_vtu_state(run.output / "vtu" / "increment_0030.vtu");
  const Eigen::MatrixXd rest = end.rest();
  double tail_x = -1e9, bulge_top = -1e9, head_top = -1e9;
  for (Eigen::Index v = 0; v < rest.rows(); ++v) {
    if (rest(v, 0) < -1e-9) continue;  // the apple's nodes (it starts in front of the mouth)
    if (rest(v, 0) > 139.99) tail_x = std::max(tail_x, end.x(v, 0));
    if (std::abs(rest(v, 0) - apple_x) < 5) bulge_top = std::max(bulge_top, end.x(v, 2));
    if (rest(v, 0) < 15) head_top = std::max(head_top, end.x(v, 2));
  }
  EXPECT_LT(tail_x - (apple_x + apple_radius), 4);
  // The tube (outer radius 12) bulges round the apple (16 measured) and not at its head.
  EXPECT_GT(bulge_top, 14.5);
  EXPECT_LT(head_top, 12.5);
  EXPECT_GT(vtu_array(read_text(run.output / "vtu" / "increment_0030.vtu"), "J").minCoeff(), 0.8);

  // The belly under the apple slides with it on the ground: left at increment 9, right at 15.
  for (const auto& [increment, side] : {std::pair{9, 1.0}, std::pair{15, -1.0}}) {
    const fs::path file = run.output / "vtu" / fmt::format("increment_{:04d}.vtu", increment);
    const VtuState state = read_vtu_state(file);
    const double x = bodies.rows.at(static_cast<std::size_t>(increment - 1)).at(0);
    double sum = 0, lift = 0;
    int count = 0;
    for (Eigen::Index v = 0; v < rest.rows(); ++v) {
      if (std::abs(rest(v, 2) + 11) > 1e-6 || rest(v, 0) < -1e-9) continue;
      lift = std::max(lift, std::abs(state.u(v, 2)));
      if (std::abs(rest(v, 0) - x) >= 5) continue;
      sum += state.u(v, 1);
      ++count;
    }
    ASSERT_GT(count, 0);
    EXPECT_GT(side * sum / count, 5) << "increment " << increment;  // 6.9 and 7.3 mm measured
    EXPECT_LT(lift, 1e-9) << "increment " << increment;
    EXPECT_GT(vtu_array(read_text(file), "J").minCoeff(), 0.8) << "increment " << increment;
  }
  std::printf("[ example  ] snake-apple: %zu steps, deepest %.3f mm, apple at x = %.2f, tail at %.2f, bulge top %.2f\n",
              steps.rows.size(), deepest, apple_x, tail_x, bulge_top);
}

}  // namespace
}  // namespace sinew::examples_test
