/// @file test_penetration_control.cpp
/// Penetration control on the contact patch test (examples/stacked-blocks.json; docs/contact.md,
/// "Penetration control"): at a penalty 100 times below the automatic one, the augmented
/// Lagrangian keeps every step's penetration below 1e-3 of the element size and carries the
/// same load as the stiff penalty; the adaptive penalty grows the pair's penalty between steps
/// until the penetration is below the tolerance. On convergence-corner, where the pressure
/// concentrates at a corner, the augmented Lagrangian reaches 1e-3 of the element size at the
/// penalty 100 times below the one the plain penalty needs for it.

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>

#include "examples/example_support.hpp"

namespace sinew::examples_test {
namespace {

constexpr double kSoftPenalty = 0.0636;  // N/mm³: the automatic penalty of the scene / 100
constexpr double kTolerance = 0.002;     // mm: 1e-3 of the blocks' element sizes (1.7 and 2.5 mm)

ExampleRun run_stacked_blocks(contact::ContactEnforcement method, const TempDir& directory, const std::string& name) {
  scene::SceneConfig config = scene::load_scene_file(example_path("stacked-blocks").string());
  config.contact.penalty = kSoftPenalty;
  config.contact.enforcement.method = method;
  config.contact.enforcement.penetration_tolerance = kTolerance;
  config.output.vtu = false;
  return run_config(std::move(config), directory, name, name);
}

TEST(PenetrationControl, AugmentedLagrangianMeetsTheToleranceAtAHundredTimesSmallerPenalty) {
  TempDir directory;
  const ExampleRun stiff = run_config(scene::load_scene_file(example_path("stacked-blocks").string()), directory,
                                      "stacked-blocks (penalty)", "penalty");
  const ExampleRun soft = run_config(
      [] {
        scene::SceneConfig c = scene::load_scene_file(example_path("stacked-blocks").string());
        c.contact.penalty = kSoftPenalty;
        return c;
      }(),
      directory, "stacked-blocks (soft penalty)", "soft");
  const ExampleRun al = run_stacked_blocks(contact::ContactEnforcement::AugmentedLagrangian, directory, "al");
  ASSERT_TRUE(stiff.report.success && soft.report.success && al.report.success) << al.report.message;
  const auto s = read_csv(stiff.output / "steps.csv");
  const auto p = read_csv(soft.output / "steps.csv");
  const auto a = read_csv(al.output / "steps.csv");
  ASSERT_EQ(a.rows.size(), 4u);
  int updates = 0;
  for (std::size_t i = 0; i < a.rows.size(); ++i) {
    EXPECT_LE(a.at(i, "max_penetration"), kTolerance) << "step " << i + 1;
    EXPECT_GT(p.at(i, "max_penetration"), 20 * kTolerance) << "the soft penalty alone penetrates far more";
    // The load the stiff penalty carries, to its own penetration (3.8e-3 mm at the end).
    EXPECT_NEAR(a.at(i, "top.fz"), s.at(i, "top.fz"), 0.01 * std::abs(s.at(i, "top.fz"))) << "step " << i + 1;
    EXPECT_NEAR(a.at(i, "bottom.fz"), -a.at(i, "top.fz"), 1e-8 * std::abs(a.at(i, "top.fz")));
    EXPECT_GT(a.at(i, "max_multiplier_pressure"), 0);
    updates += static_cast<int>(a.at(i, "multiplier_updates"));
  }
  EXPECT_GT(updates, 0);
  EXPECT_LE(updates, 4 * 20);
  int newton_stiff = 0, newton_al = 0;
  for (std::size_t i = 0; i < a.rows.size(); ++i) {
    newton_stiff += static_cast<int>(s.at(i, "newton_iterations"));
    newton_al += static_cast<int>(a.at(i, "newton_iterations"));
  }
  std::printf("[ example  ] stacked-blocks: penalty %.4g: %d Newton its, penetration %.3g mm, load %.5f N; "
              "penalty %.4g + augmented Lagrangian: %d Newton its (%d multiplier updates), penetration %.3g mm, "
              "load %.5f N; penalty %.4g alone: penetration %.3g mm\n",
              6.36, newton_stiff, s.at(3, "max_penetration"), -s.at(3, "top.fz"), kSoftPenalty, newton_al, updates,
              a.at(3, "max_penetration"), -a.at(3, "top.fz"), kSoftPenalty, p.at(3, "max_penetration"));
}

TEST(PenetrationControl, AdaptivePenaltyGrowsBetweenStepsUntilThePenetrationIsBelowTheTolerance) {
  TempDir directory;
  const ExampleRun run = run_stacked_blocks(contact::ContactEnforcement::AdaptivePenalty, directory, "adaptive");
  ASSERT_TRUE(run.report.success) << run.report.message;
  const auto steps = read_csv(run.output / "steps.csv");
  ASSERT_EQ(steps.rows.size(), 4u);
  double previous = 0;
  for (std::size_t i = 0; i < steps.rows.size(); ++i) {
    const double penalty = steps.at(i, "contact.lower.upper.penalty");
    EXPECT_GE(penalty, previous) << "step " << i + 1;
    previous = penalty;
  }
  // The column is the penalty after the step (the next step's): already grown after the first.
  EXPECT_GT(steps.at(0, "contact.lower.upper.penalty"), kSoftPenalty);
  EXPECT_GT(steps.at(3, "contact.lower.upper.penalty"), 100 * kSoftPenalty);
  EXPECT_GT(steps.at(0, "max_penetration"), 10 * kTolerance);
  EXPECT_LE(steps.at(3, "max_penetration"), kTolerance);
  std::printf("[ example  ] stacked-blocks adaptive penalty: %.4g -> %.4g N/mm3, penetration %.3g -> %.3g mm\n",
              kSoftPenalty, steps.at(3, "contact.lower.upper.penalty"), steps.at(0, "max_penetration"),
              steps.at(3, "max_penetration"));
}

}  // namespace
namespace {

/// convergence-corner's first 2e-4 s (the dynamic approach from its interpenetrated start, with
/// the scene's penalty 100), then a static stage from there with `configure` applied.
ExampleRun corner_stage(const TempDir& directory, const std::string& name,
                        const std::function<void(scene::SceneConfig&)>& configure) {
  const fs::path approach = directory.path() / "approach";
  if (!fs::exists(approach / "checkpoint.cbor")) {
    scene::SceneConfig c = scene::load_scene_file(example_path("convergence-corner").string());
    c.dynamics.options.end_time = 2e-4;
    c.dynamics.options.output_interval = 2e-4;
    c.output.vtu = false;
    const ExampleRun run = run_config(std::move(c), directory, "convergence-corner, approach", "approach");
    EXPECT_TRUE(run.report.success) << run.report.message;
  }
  scene::SceneConfig c = scene::load_scene_file(example_path("convergence-corner").string());
  c.dynamics.enabled = false;
  c.initial_state = approach.string();
  c.solver.stepping.increments = 1;
  c.output.vtu = false;
  configure(c);
  return run_config(std::move(c), directory, name, name);
}

}  // namespace

TEST(PenetrationControl, AugmentedLagrangianReachesAThousandthOfTheElementSizeAtTheCorner) {
  // 1e-3 of the contact surfaces' mean edge (0.859 mm). The plain penalty needs 5e5 N/mm³ for
  // it (3e5 leaves 0.00108 mm); the augmented Lagrangian gets there at 5e3.
  constexpr double kCornerTolerance = 0.000859;
  TempDir directory;
  const ExampleRun stiff = corner_stage(directory, "corner-penalty", [](scene::SceneConfig& c) { c.contact.penalty = 5e5; });
  const ExampleRun soft = corner_stage(directory, "corner-soft", [](scene::SceneConfig& c) { c.contact.penalty = 5e3; });
  const ExampleRun al = corner_stage(directory, "corner-al", [&](scene::SceneConfig& c) {
    c.contact.penalty = 5e3;
    c.contact.enforcement.method = contact::ContactEnforcement::AugmentedLagrangian;
    c.contact.enforcement.penetration_tolerance = kCornerTolerance;
    c.contact.enforcement.max_updates = 60;
  });
  ASSERT_TRUE(stiff.report.success && soft.report.success && al.report.success) << al.report.message;
  const auto s = read_csv(stiff.output / "steps.csv");
  const auto p = read_csv(soft.output / "steps.csv");
  const auto a = read_csv(al.output / "steps.csv");
  EXPECT_LE(s.at(0, "max_penetration"), kCornerTolerance);
  EXPECT_GT(p.at(0, "max_penetration"), 10 * kCornerTolerance) << "the soft penalty alone penetrates far more";
  EXPECT_LE(a.at(0, "max_penetration"), kCornerTolerance);
  EXPECT_LT(a.at(0, "multiplier_updates"), 60) << "the tolerance was met, not the cap";
  // The same equilibrium as the stiff penalty: the reaction at the right slab's end.
  EXPECT_NEAR(a.at(0, "right-end.fx"), s.at(0, "right-end.fx"), 1e-3 * std::abs(s.at(0, "right-end.fx")));
  std::printf("[ example  ] convergence-corner: penalty 5e5: %d Newton its, %.2f s, penetration %.3g mm, reaction %.5f N; "
              "penalty 5e3 + augmented Lagrangian: %d Newton its (%.0f multiplier updates), %.2f s, penetration %.3g mm, "
              "reaction %.5f N; penalty 5e3 alone: penetration %.3g mm\n",
              stiff.report.result.newton_iterations, stiff.seconds, s.at(0, "max_penetration"), s.at(0, "right-end.fx"),
              al.report.result.newton_iterations, a.at(0, "multiplier_updates"), al.seconds, a.at(0, "max_penetration"),
              a.at(0, "right-end.fx"), p.at(0, "max_penetration"));
}

}  // namespace sinew::examples_test
