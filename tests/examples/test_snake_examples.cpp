/// @file test_snake_examples.cpp
/// The dissertation's coiling snake (Fig. 49, examples/coiling-snake.json from
/// scripts/make_coiling_snake.py): the head, moved by keyframes toward the fixed tail while it
/// turns, coils the rod into a loop that closes on itself; self-contact keeps it from passing
/// through, no element inverts, and the rod is in equilibrium between its two ends.

#include <gtest/gtest.h>

#include <cstdio>

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

}  // namespace
}  // namespace sinew::examples_test
