/// @file test_knee_examples.cpp
/// The knee flexion (issue 6, dissertation section 7) on a coarse variant of
/// examples/knee-flexion.json: 20 mm elements and the first 30 degrees of flexion in 10
/// increments of 3 degrees, the seed's increment. Asserts what the seed's Figs. 42-43 show:
/// nothing inverts, penetration stays bounded, and the free patella, pulled by the patellar
/// ligament, moves distally and slides round the femur, on the groove, as the flexion grows.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "examples/example_support.hpp"

namespace sinew::examples_test {
namespace {

TEST(KneeExamples, CoarseFlexionMovesThePatellaDistallyWithoutInversionOrDeepPenetration) {
  scene::SceneConfig config = scene::load_scene_file(example_path("knee-flexion").string());
  ASSERT_EQ(config.bodies.size(), 2u);
  for (auto& body : config.bodies) body.mesh.generate.element_size = 20;
  auto& tibia = config.bodies.at(1).regions.at("tibia");
  ASSERT_TRUE(tibia.rigid);
  ASSERT_EQ(tibia.rigid_kind, fem::RigidBody::Kind::Prescribed);
  ASSERT_NEAR(tibia.rigid_motion.angle, 150.0 * M_PI / 180.0, 1e-12);
  tibia.rigid_motion.angle = 30.0 * M_PI / 180.0;
  config.solver.stepping.increments = 10;
  TempDir directory;
  const ExampleRun run = run_config(config, directory, "knee-flexion (20 mm, 30 degrees)");
  ASSERT_TRUE(run.report.success) << run.report.message;
  EXPECT_EQ(run.report.result.segments_completed, 10);

  const auto steps = read_csv(run.output / "steps.csv");
  const auto rigid = read_csv(run.output / "rigid_bodies.csv");
  ASSERT_EQ(rigid.rows.size(), steps.rows.size());
  const double max_penetration = steps.column_max("max_penetration");
  const double skin_thickness = 10;  // mm, scripts/make_knee.py
  std::printf("[ example  ] knee-flexion coarse: %d steps, %d Newton iterations, %d cuts, max penetration %.3f mm "
              "(%.1f %% of the skin's thickness)\n",
              run.report.result.steps, run.report.result.newton_iterations, run.report.result.cuts, max_penetration,
              100 * max_penetration / skin_thickness);
  EXPECT_LT(max_penetration, 0.15 * skin_thickness);

  // The tibia turns as prescribed; the patella, free, follows the ligament: down and back,
  // rotating with the flexion but less.
  // Its angle about the flexion axis (the y axis; 0 straight up, 90 degrees straight ahead).
  auto around_axis = [](double x, double z) { return std::atan2(x, z) * 180 / M_PI; };
  double previous_z = 1e300, previous_angle = -1e300;
  for (std::size_t i = 0; i < rigid.rows.size(); ++i) {
    const double lambda = rigid.at(i, "lambda");
    EXPECT_NEAR(rigid.at(i, "leg/tibia.angle_deg"), 30 * lambda, 1e-9);
    const double x = rigid.at(i, "leg/patella.x"), z = rigid.at(i, "leg/patella.z");
    std::printf("[ example  ] knee-flexion coarse: %4.1f deg  patella x %.2f y %.2f z %.2f mm, turned %.2f deg\n",
                30 * lambda, x, rigid.at(i, "leg/patella.y"), z, rigid.at(i, "leg/patella.angle_deg"));
    EXPECT_LT(z, previous_z) << "the patella moves distally, row " << i;
    EXPECT_GT(around_axis(x, z), previous_angle) << "the patella slides on round the femur, row " << i;
    // It rides on the femur, not in it: its centre stays outside the groove's floor (radius 19
    // about the flexion axis, the y axis) plus its own radius (14), up to a few mm of penetration.
    EXPECT_GT(std::hypot(x, z), 19 + 14 - 3) << "row " << i;
    EXPECT_NEAR(rigid.at(i, "leg/patella.y"), 0, 1) << "the symmetric leg keeps the patella centred, row " << i;
    previous_z = z;
    previous_angle = around_axis(x, z);
  }
  const std::size_t last = rigid.rows.size() - 1;
  EXPECT_LT(rigid.at(last, "leg/patella.z"), rigid.at(0, "leg/patella.z") - 5) << "at least 5 mm distally";
  EXPECT_GT(around_axis(rigid.at(last, "leg/patella.x"), rigid.at(last, "leg/patella.z")),
            around_axis(rigid.at(0, "leg/patella.x"), rigid.at(0, "leg/patella.z")) + 15)
      << "at least 15 degrees round the condyles";
  EXPECT_LT(std::hypot(rigid.at(last, "leg/patella.x"), rigid.at(last, "leg/patella.z")), 19 + 14 + 3)
      << "by 30 degrees the ligament has pulled the patella onto the groove";
  EXPECT_GT(rigid.at(last, "leg/patella.angle_deg"), 2);
  EXPECT_LT(rigid.at(last, "leg/patella.angle_deg"), 30);

  // No inverted element at any increment: J > 0 in every tet (rigid tets keep J = 1).
  for (const auto& entry : read_pvd(run.output / "sinew.pvd")) {
    const Eigen::MatrixXd J = vtu_array(read_text(run.output / entry.file), "J");
    EXPECT_GT(J.minCoeff(), 0) << entry.file;
  }
}

}  // namespace
}  // namespace sinew::examples_test
