/// @file test_vh_knee_example.cpp
/// The knee flexion on the Visible Human surfaces (examples/vh-knee-flexion.json, issue 14), coarse:
/// 22 mm elements (size zones scaled with it) and the first 45 degrees in 15 increments of 3. Runs
/// only where the HRA files are at ../shared/data/vh-knee beside the repository (the scene's
/// data_dir); says visibly that it was skipped otherwise. Asserts: the run completes, nothing
/// inverts, penetration stays under 10 % of the skin-fat layer (8 mm), and the free patella rides
/// the femoral groove: it moves distally and posteriorly and flexes with the knee.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "examples/example_support.hpp"
#include "sinew/scene/element_size.hpp"

namespace sinew::examples_test {
namespace {

TEST(VhKneeExample, CoarseFlexionKeepsThePatellaInTheGroove) {
  scene::SceneConfig config = scene::load_scene_file(example_path("vh-knee-flexion").string());
  if (!std::filesystem::exists(std::filesystem::path(config.data_directory) / "VH_M_Knee_R.glb")) {
    std::printf("[ skipped  ] VH knee: the HRA files are not in %s\n", config.data_directory.c_str());
    GTEST_SKIP() << "VH knee data not found in " << config.data_directory;
  }
#ifdef SINEW_SANITIZER_BUILD
  // CGAL's mesher and the 26k-unknown solve run ~10x slower instrumented: the Release suite
  // covers this run; the sanitizers see the same code on the small scenes of the other suites.
  std::printf("[ skipped  ] VH knee flexion: not in the sanitizer build (about an hour there)\n");
  GTEST_SKIP() << "not in the sanitizer build";
#endif
  ASSERT_EQ(config.bodies.size(), 2u);
  for (const auto& body : config.bodies) ASSERT_TRUE(body.mesh.surfaces.has_value());
  scene::set_element_size(config, 22);
  auto& tibia = config.bodies.at(1).regions.at("tibia");
  ASSERT_EQ(tibia.rigid_kind, fem::RigidBody::Kind::Prescribed);
  ASSERT_NEAR(tibia.rigid_motion.angle, 150.0 * M_PI / 180.0, 1e-12);
  tibia.rigid_motion.angle = 45.0 * M_PI / 180.0;
  config.solver.stepping.increments = 15;
  TempDir directory;
  const ExampleRun run = run_config(config, directory, "vh-knee-flexion (22 mm, 45 degrees)");
  ASSERT_TRUE(run.report.success) << run.report.message;
  EXPECT_EQ(run.report.result.segments_completed, 15);

  const auto steps = read_csv(run.output / "steps.csv");
  const auto rigid = read_csv(run.output / "rigid_bodies.csv");
  const double max_penetration = steps.column_max("max_penetration");
  const double skin_fat = 8;  // mm, scripts/make_vh_knee.py
  std::printf("[ example  ] vh-knee coarse: %d steps, %d Newton iterations, %d cuts, max penetration %.3f mm "
              "(%.1f %% of the skin-fat layer)\n",
              run.report.result.steps, run.report.result.newton_iterations, run.report.result.cuts, max_penetration,
              100 * max_penetration / skin_fat);
  EXPECT_LT(max_penetration, 0.10 * skin_fat);

  // The data's frame: +y up, +z anterior. The patella moves down (distal) and back (posterior)
  // and turns with the knee (its flexion about the epicondylar axis grows).
  const std::size_t last = rigid.rows.size() - 1;
  for (std::size_t i = 0; i < rigid.rows.size(); ++i) {
    std::printf("[ example  ] vh-knee coarse: %4.1f deg  patella x %.2f y %.2f z %.2f mm, turned %.2f deg\n",
                45 * rigid.at(i, "lambda"), rigid.at(i, "leg/patella.x"), rigid.at(i, "leg/patella.y"),
                rigid.at(i, "leg/patella.z"), rigid.at(i, "leg/patella.angle_deg"));
  }
  EXPECT_LT(rigid.at(last, "leg/patella.y"), rigid.at(0, "leg/patella.y") - 3) << "distally";
  EXPECT_LT(rigid.at(last, "leg/patella.z"), rigid.at(0, "leg/patella.z") - 1) << "posteriorly";
  EXPECT_GT(rigid.at(last, "leg/patella.angle_deg"), 5) << "the patella flexes with the knee";
  EXPECT_LT(rigid.at(last, "leg/patella.angle_deg"), 45);

  for (const auto& entry : read_pvd(run.output / "sinew.pvd")) {
    const Eigen::MatrixXd J = vtu_array(read_text(run.output / entry.file), "J");
    EXPECT_GT(J.minCoeff(), 0) << entry.file;
  }
}

}  // namespace
}  // namespace sinew::examples_test
