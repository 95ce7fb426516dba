/// @file test_friction_examples.cpp
/// Coulomb friction on examples/block-on-incline.json (docs/contact.md, "Friction"): a rigid block
/// on a rigid plane under gravity tilted by θ. It slides with acceleration g (sin θ - μ cos θ)
/// when tan θ > μ (within 2 %, the bound) and sticks when tan θ < μ: its slip per step
/// stays below the slip threshold (the smoothed law's creep) and it does not accelerate. The
/// friction force over the normal force is μ while it slides. And Puso and Laursen's ironing
/// problem (examples/ironing.json, coarsened): in steady sliding the friction force is μ times the
/// normal contact force within 3 %. A slip threshold in velocity units keeps the creep of the stuck
/// block at the same velocity whatever the time step. The falling rods with mu = 0.5 stay where
/// they land on the bar, where without friction they slide along it. The sheared blocks
/// (examples/sheared-blocks.json) pass the frictional patch test: pressed, then sheared below the
/// stick limit by the tractions of one uniform stress, both blocks deform homogeneously and the
/// interface does not slip.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "examples/example_support.hpp"

namespace sinew::examples_test {
namespace {

constexpr double kG = 9810.0;  // mm/s²

struct Incline {
  ExampleRun run;
  double acceleration = 0;  ///< fitted over the second half of the run (mm/s²)
  double travel = 0;        ///< block's x at the end minus at the start (mm)
  double largest_angle = 0;  ///< of the block's rotation (degrees)
  CsvTable steps;
};

/// Runs the example with gravity tilted by theta (degrees) and friction coefficient mu, after
/// `change` (if any) changed its configuration.
Incline run_incline(double theta_deg, double mu, const TempDir& directory, const std::string& name,
                    const std::function<void(scene::SceneConfig&)>& change = {}) {
  scene::SceneConfig config = scene::load_scene_file(example_path("block-on-incline").string());
  if (change) change(config);
  const double theta = theta_deg * M_PI / 180;
  config.loads.gravity = Vector3(kG * std::sin(theta), 0, -kG * std::cos(theta));
  config.contact.friction.coefficient = mu;
  config.output.vtu = false;
  Incline result;
  result.run = run_config(std::move(config), directory, name, name);
  const auto bodies = read_csv(result.run.output / "rigid_bodies.csv");
  result.steps = read_csv(result.run.output / "steps.csv");
  const auto t = bodies.column("time");
  const auto x = bodies.column("block/block.x");
  const auto angle = bodies.column("block/block.angle_deg");
  // x(t) = x0 + v0 t + a t² / 2 by least squares over the second half (implicit Euler moves a
  // constant acceleration's parabola by a h t / 2, which v0 absorbs).
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < t.size(); ++i) {
    result.largest_angle = std::max(result.largest_angle, angle[i]);
    if (t[i] < t.back() / 2) continue;
    const Eigen::Vector3d phi(1, t[i], t[i] * t[i] / 2);
    A += phi * phi.transpose();
    b += phi * x[i];
  }
  result.acceleration = A.ldlt().solve(b)[2];
  result.travel = x.back() - x.front();
  return result;
}

/// The simulated time of a run (s).
double config_end_time(const Incline& r) { return r.run.config.dynamics.options.end_time; }

TEST(FrictionExamples, BlockSlidesDownTheInclineWithCoulombsAcceleration) {
  TempDir directory;
  for (const auto& [theta, mu] : {std::pair{30.0, 0.3}, std::pair{20.0, 0.3}, std::pair{30.0, 0.0}}) {
    const Incline r = run_incline(theta, mu, directory, "incline-" + std::to_string(int(theta)) + "-" + std::to_string(int(100 * mu)));
    ASSERT_TRUE(r.run.report.success) << r.run.report.message;
    const double t = theta * M_PI / 180;
    const double expected = kG * (std::sin(t) - mu * std::cos(t));
    std::printf("[ example  ] block on incline, theta %.0f, mu %.1f: acceleration %.2f mm/s^2 (Coulomb %.2f, ratio "
                "%.4f), largest rotation %.3f deg\n",
                theta, mu, r.acceleration, expected, r.acceleration / expected, r.largest_angle);
    EXPECT_NEAR(r.acceleration, expected, 0.02 * expected);
    EXPECT_LT(r.largest_angle, 1.0);  // it slides, it does not tumble
    if (mu > 0) {
      const std::size_t last = r.steps.rows.size() - 1;
      const double ratio = r.steps.at(last, "contact.ground.block.friction_fx") /
                           std::abs(r.steps.at(last, "contact.ground.block.fz"));
      EXPECT_NEAR(ratio, mu, 0.01 * mu);  // friction on the ground from the block: μ N down the slope
    }
  }
}

TEST(FrictionExamples, BlockSticksWhenTheSlopeIsBelowTheFrictionAngle) {
  TempDir directory;
  const Incline r = run_incline(10.0, 0.3, directory, "incline-stick");
  ASSERT_TRUE(r.run.report.success) << r.run.report.message;
  const double frictionless = kG * std::sin(10.0 * M_PI / 180);
  // The smoothed law creeps: per step the block slips s with f1(s) = tan θ / μ < 1, a fixed
  // fraction of the threshold (default 1e-3 of the mean surface edge).
  const std::size_t steps = r.steps.rows.size() - 1;
  const double per_step = r.travel / static_cast<double>(steps);
  std::printf("[ example  ] block on incline, theta 10, mu 0.3: acceleration %.4f mm/s^2 (frictionless %.1f), "
              "travel %.4f mm over %zu steps (%.5f mm per step)\n",
              r.acceleration, frictionless, r.travel, steps, per_step);
  EXPECT_LT(std::abs(r.acceleration), 1e-3 * frictionless);
  EXPECT_GT(per_step, 0);
  EXPECT_LT(per_step, 0.01);  // the threshold here is about 0.008 mm
  const std::size_t last = r.steps.rows.size() - 1;
  const double ratio = r.steps.at(last, "contact.ground.block.friction_fx") /
                       std::abs(r.steps.at(last, "contact.ground.block.fz"));
  EXPECT_NEAR(ratio, std::tan(10.0 * M_PI / 180), 0.01);  // static friction balances the slope
}

TEST(FrictionExamples, ASlipVelocityThresholdBoundsTheCreepWhateverTheTimeStep) {
  // Stuck at 10 degrees (tan = 0.176 < mu = 0.3). A threshold in length creeps the same length
  // per step, so its creep velocity grows as the step shrinks (2.9 mm/s at 1 ms, 10.9 at
  // 0.25 ms measured); a threshold in velocity, eps_v h per step, creeps at the same velocity
  // (0.36 eps_v, the smoothed law's stick: f1(s) = tan / mu) whatever the step.
  TempDir directory;
  const double eps_v = 0.5;  // mm/s
  std::vector<double> creep;
  for (const double h : {1e-3, 2.5e-4}) {
    const std::string name = "incline-stick-velocity-" + std::to_string(static_cast<int>(1e5 * h));
    const Incline r = run_incline(10.0, 0.3, directory, name, [&](scene::SceneConfig& config) {
      config.contact.friction.slip_velocity_threshold = eps_v;
      config.dynamics.options.time_step = config.dynamics.options.max_time_step = h;
    });
    ASSERT_TRUE(r.run.report.success) << r.run.report.message;
    creep.push_back(r.travel / config_end_time(r));
    std::printf("[ example  ] block on incline, theta 10, mu 0.3, slip velocity %.2f mm/s, h %.2g s: creep %.4f mm/s\n",
                eps_v, h, creep.back());
    EXPECT_GT(creep.back(), 0);
    EXPECT_LT(creep.back(), 0.5 * eps_v);
    EXPECT_LT(std::abs(r.acceleration), 1e-3 * kG * std::sin(10.0 * M_PI / 180));
  }
  EXPECT_NEAR(creep[1], creep[0], 0.02 * creep[0]);
}

/// The falling rods reduced as in DynamicsExamples (2 x 3 rods, 0.5 s) with friction `mu`
/// between every pair of bodies; returns the mean slide (mm) along the bar, between t = 0.2 and
/// t = 0.5, of the rods' nodes that lie on the bar at the end.
double rods_slide_along_the_bar(double mu, const TempDir& directory, double& friction_force) {
  scene::SceneConfig config = reduced_falling_rods();
  config.contact.friction.coefficient = mu;
  const std::string name = "falling-rods-mu-" + std::to_string(static_cast<int>(10 * mu));
  const ExampleRun run = run_config(config, directory, name, name);
  EXPECT_TRUE(run.report.success) << run.report.message;
  // The bar: an arc of a torus about the vertical through `center`.
  const mesh::Shape& bar = config.bodies.at(3).mesh.parts.at(0).shape;
  EXPECT_EQ(config.bodies.at(3).name, "bar");
  auto distance_to_bar = [&](const Eigen::Vector3d& x) {
    const Eigen::Vector3d v = x - bar.center;
    return std::hypot(std::hypot(v.x(), v.y()) - bar.radius, v.z()) - bar.minor_radius;
  };
  const VtuState landed = read_vtu_state(run.output / "vtu" / "output_0002.vtu");
  const VtuState end = read_vtu_state(run.output / "vtu" / "output_0005.vtu");
  const Eigen::MatrixXd rest = end.rest();
  double slide = 0;
  int on_bar = 0;
  for (Eigen::Index v = 0; v < rest.rows(); ++v) {
    if (distance_to_bar(rest.row(v).transpose()) < 0.003) continue;  // the bar's own nodes
    if (distance_to_bar(end.x.row(v).transpose()) > 0.0015) continue;  // not on the bar
    const Eigen::Vector3d arm = landed.x.row(v).transpose() - bar.center;
    const Eigen::Vector3d along = Eigen::Vector3d(-arm.y(), arm.x(), 0).normalized();
    slide += std::abs((end.x.row(v) - landed.x.row(v)).dot(along.transpose()));
    ++on_bar;
  }
  EXPECT_GT(on_bar, 5) << "the rods lie on the bar at the end";
  const auto steps = read_csv(run.output / "steps.csv");
  friction_force = 0;
  if (mu > 0) {
    const std::size_t last = steps.rows.size() - 1;
    friction_force = Eigen::Vector3d(steps.at(last, "contact.rods.bar.friction_fx"),
                                     steps.at(last, "contact.rods.bar.friction_fy"),
                                     steps.at(last, "contact.rods.bar.friction_fz"))
                         .norm();
  }
  return 1e3 * slide / std::max(on_bar, 1);
}

TEST(FrictionExamples, FallingRodsStayWhereTheyLandOnTheBarWithFriction) {
#ifdef SINEW_SANITIZER_BUILD
  GTEST_SKIP() << "two falling-rod runs take many minutes instrumented; the Release suite runs them";
#endif
  // Without friction the rods slide off along the curved bar (3.3 mm from t = 0.2 to 0.5 s,
  // measured); with mu = 0.5 they stay where they landed (0.05 mm).
  TempDir directory;
  double frictionless_force = 0, friction_force = 0;
  const double frictionless = rods_slide_along_the_bar(0.0, directory, frictionless_force);
  const double sticking = rods_slide_along_the_bar(0.5, directory, friction_force);
  std::printf("[ example  ] falling rods on the bar, t 0.2 -> 0.5 s: mean slide along the bar %.3f mm (mu 0), %.3f mm "
              "(mu 0.5); friction force from the bar %.4f N\n",
              frictionless, sticking, friction_force);
  EXPECT_GT(frictionless, 1.0);
  EXPECT_LT(sticking, 0.2);
  EXPECT_LT(sticking, 0.1 * frictionless);
  EXPECT_GT(friction_force, 1e-3);
}

TEST(FrictionExamples, IroningDieSlidesWithFrictionMuTimesTheNormalForce) {
  // The example has 0.6 mm and 40 increments. Instrumented, 1 mm and 16 increments (7 steps of
  // steady sliding, friction / normal 0.305, measured): the 0.75 mm run took 227 s there.
#ifdef SINEW_SANITIZER_BUILD
  constexpr double kElementSize = 1.0;
  constexpr int kIncrements = 16;
#else
  constexpr double kElementSize = 0.75;
  constexpr int kIncrements = 24;
#endif
  scene::SceneConfig config = scene::load_scene_file(example_path("ironing").string());
  config.bodies[0].mesh.generate.element_size = kElementSize;
  config.bodies[1].mesh.generate.element_size = kElementSize;
  config.solver.stepping.increments = kIncrements;
  config.output.vtu = false;
  TempDir directory;
  const ExampleRun run = run_config(std::move(config), directory,
                                    fmt::format("ironing ({} mm, {} increments)", kElementSize, kIncrements));
  ASSERT_TRUE(run.report.success) << run.report.message;
  const auto steps = read_csv(run.output / "steps.csv");
  double friction_ratio = 0, die_ratio = 0;
  int sliding = 0;
  for (std::size_t i = 0; i < steps.rows.size(); ++i) {
    const double lambda = steps.at(i, "lambda");
    if (lambda < 0.25 + 0.75 / 2) continue;  // steady sliding: the second half of the slide
    const double ratio = steps.at(i, "contact.slab.die.friction_fx") / -steps.at(i, "contact.slab.die.fz");
    EXPECT_NEAR(ratio, 0.3, 0.03 * 0.3) << "lambda " << lambda;
    friction_ratio += ratio;
    die_ratio += steps.at(i, "die_x.fx") / -steps.at(i, "die_z.fz");
    ++sliding;
  }
  ASSERT_GT(sliding, 5);
  std::printf("[ example  ] ironing: steady sliding over %d steps: friction / normal contact force %.4f, die "
              "horizontal / vertical reaction %.4f (mu 0.3; the excess is the pressure of the slab piled up "
              "ahead of the die), largest penetration %.3f mm\n",
              sliding, friction_ratio / sliding, die_ratio / sliding, steps.column_max("max_penetration"));
  EXPECT_GT(die_ratio / sliding, 0.3);  // the pile-up ahead adds pressure: never less than friction alone
  EXPECT_LT(die_ratio / sliding, 0.45);
}

/// The affine map x = A X + b fitted by least squares to the nodes `rows` of a state; the largest
/// distance of those nodes from it in `residual`. Normal equations in fixed-size matrices: libgmsh
/// instantiates Eigen's dynamic-size decompositions too (its fullMatrix::luSolve uses
/// ColPivHouseholderQR<MatrixXd>), and an instantiation of ours would take the place of its own,
/// with allocations that do not match under AddressSanitizer (a bad free inside Gmsh's meshing).
struct AffineFit {
  Eigen::Matrix3d A;
  Eigen::Vector3d b;
  double residual = 0;
  Eigen::Vector3d at(const Eigen::Vector3d& X) const { return A * X + b; }
};

AffineFit fit_affine(const VtuState& state, const std::vector<Eigen::Index>& rows) {
  const Eigen::MatrixXd X = state.rest();
  Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
  Eigen::Matrix<double, 4, 3> right = Eigen::Matrix<double, 4, 3>::Zero();
  for (const Eigen::Index v : rows) {
    const Eigen::Vector4d phi(X(v, 0), X(v, 1), X(v, 2), 1);
    normal += phi * phi.transpose();
    right += phi * state.x.row(v);
  }
  const Eigen::Matrix<double, 4, 3> coefficients = normal.ldlt().solve(right);
  AffineFit fit;
  fit.A = coefficients.topRows<3>().transpose();
  fit.b = coefficients.row(3).transpose();
  for (const Eigen::Index v : rows) {
    const Eigen::Vector3d rest(X(v, 0), X(v, 1), X(v, 2));
    fit.residual = std::max(fit.residual, (fit.at(rest) - state.x.row(v).transpose()).norm());
  }
  return fit;
}

// sheared-blocks: the frictional contact patch test.
TEST(FrictionExamples, ShearedBlocksPassTheFrictionalPatchTest) {
  TempDir directory;
  const ExampleRun run = run_example("sheared-blocks", directory);
  expect_complete_outputs(run);
  ASSERT_TRUE(run.report.success) << run.report.message;
  constexpr double kShear = 0.0025, kMu = 0.5, kArea = 100;  // MPa, mm²
  const auto steps = read_csv(run.output / "steps.csv");
  const std::size_t last = steps.rows.size() - 1;
  // The interface carries the load: the top's reaction as normal contact force, the shear as
  // friction, below the stick limit.
  const double normal = -steps.at(last, "top.fz");
  EXPECT_NEAR(normal, 1.01, 0.01);  // the 0.1 mm press: a pressure of 0.0101 MPa
  EXPECT_NEAR(steps.at(last, "contact.lower.upper.fz"), -normal, 1e-4 * normal);
  EXPECT_NEAR(steps.at(last, "contact.lower.upper.friction_fx"), kShear * kArea, 1e-3 * kShear * kArea);
  EXPECT_LT(steps.at(last, "contact.lower.upper.friction_fx"), 0.6 * kMu * normal);
  // Uniform pressure: the penetration is the same everywhere on the interface.
  EXPECT_LT(steps.at(last, "max_penetration"), 1.03 * steps.at(last, "mean_penetration"));

  // Homogeneous deformation of each block: an affine map fits its nodes (those off the
  // interface, whose rest positions both blocks share) to round-off of the solve.
  const auto pvd = read_pvd(run.output / "sinew.pvd");
  auto state_at = [&](double lambda) {
    for (const PvdEntry& entry : pvd)
      if (std::abs(entry.time - lambda) < 1e-9) return read_vtu_state(run.output / entry.file);
    ADD_FAILURE() << "no output at lambda " << lambda;
    return read_vtu_state(run.output / pvd.back().file);
  };
  const VtuState pressed = state_at(0.5), sheared = state_at(1.0);
  const Eigen::MatrixXd X = sheared.rest();
  std::vector<Eigen::Index> lower, upper;
  for (Eigen::Index v = 0; v < X.rows(); ++v) {
    if (X(v, 2) < 4.999 - 1e-6) lower.push_back(v);  // the upper block starts at z = 4.999
    if (X(v, 2) > 5 + 1e-6) upper.push_back(v);
  }
  const AffineFit lower_fit = fit_affine(sheared, lower), upper_fit = fit_affine(sheared, upper);
  const double shear_displacement = (sheared.u - pressed.u).col(0).cwiseAbs().maxCoeff();
  // Both blocks have the same deformation gradient: the same stress.
  const double gradient_difference = (lower_fit.A - upper_fit.A).cwiseAbs().maxCoeff();
  const double shear_strain = upper_fit.A(0, 2);
  // Slip: the change of the tangential jump across the interface during the shear.
  const AffineFit lower_pressed = fit_affine(pressed, lower), upper_pressed = fit_affine(pressed, upper);
  double slip = 0;
  for (const Eigen::Vector3d& at : {Eigen::Vector3d(0, 0, 5), Eigen::Vector3d(10, 0, 5), Eigen::Vector3d(0, 10, 5),
                                   Eigen::Vector3d(10, 10, 5)}) {
    const Eigen::Vector3d jump = (upper_fit.at(at) - lower_fit.at(at)) - (upper_pressed.at(at) - lower_pressed.at(at));
    slip = std::max(slip, std::hypot(jump.x(), jump.y()));
  }
  std::printf("[ example  ] sheared-blocks: friction %.6f N (applied shear %.6f N), normal %.6f N; affine fit "
              "residual %.2e / %.2e mm; shear strain %.5f, difference of the blocks' gradients %.2e; shear "
              "displacement %.4f mm, interface slip %.2e mm\n",
              steps.at(last, "contact.lower.upper.friction_fx"), kShear * kArea, normal,
              lower_fit.residual, upper_fit.residual, shear_strain, gradient_difference, shear_displacement, slip);
  // Measured: residuals 1.4e-4 and 1.5e-4 mm (0.2 % of the shear displacement, 0.1 % of the whole),
  // gradients 0.2 % of the shear strain apart: the non-matching meshes' penalty interface.
  EXPECT_LT(lower_fit.residual, 5e-3 * shear_displacement);
  EXPECT_LT(upper_fit.residual, 5e-3 * shear_displacement);
  EXPECT_LT(gradient_difference, 5e-3 * shear_strain);
  // The linear shear strain tau / G, G = E / (2 (1 + nu)).
  EXPECT_NEAR(shear_strain, kShear / (1.0 / 2.6), 0.03 * kShear / (1.0 / 2.6));
  // Stuck: the smoothed law's creep only, below one slip threshold (1e-3 of the mean surface
  // edge) over the four shear steps; measured 1.4e-3 mm, 2 % of the shear displacement.
  EXPECT_LT(slip, 0.03 * shear_displacement);
}

}  // namespace
}  // namespace sinew::examples_test
