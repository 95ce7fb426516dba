/// @file test_examples.cpp
/// Every scene in examples/ is a regression test: it runs through the library (load_scene_file
/// + run_scene, as `sinew run` does) into a scratch directory, writes complete outputs, and its
/// results match a closed form, an equilibrium identity, or a recorded value.
///
/// One TEST per example, so that each example is solved once whether the binary runs whole or
/// ctest runs each test in its own process.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <variant>

#include <nlohmann/json.hpp>

#include "examples/example_support.hpp"

namespace sinew::examples_test {
namespace {

// ---------------------------------------------------------------------------------------------
// uniaxial-mooney-rivlin: closed form of the seed's Mooney-Rivlin law in uniaxial tension.

struct MooneyRivlin {
  double C1, C2, a;
};

/// Zero lateral stress for F = diag(l, s, s):
/// 2 C1 s + 2 C2 s (l^2 + s^2) + 2 a s^3 l^2 - 2 (C1 + 2 C2 + a) / s = 0, solved by Newton from s = 1.
double lateral_stretch(const MooneyRivlin& m, double l) {
  const double K = m.C1 + 2 * m.C2 + m.a;
  double s = 1.0;
  for (int i = 0; i < 100; ++i) {
    const double f = 2 * m.C1 * s + 2 * m.C2 * s * (l * l + s * s) + 2 * m.a * s * s * s * l * l - 2 * K / s;
    const double df = 2 * m.C1 + 2 * m.C2 * (l * l + 3 * s * s) + 6 * m.a * s * s * l * l + 2 * K / (s * s);
    const double ds = f / df;
    s -= ds;
    if (std::abs(ds) < 1e-15) break;
  }
  return s;
}

/// Axial nominal (first Piola-Kirchhoff) stress.
double axial_nominal_stress(const MooneyRivlin& m, double l, double s) {
  const double K = m.C1 + 2 * m.C2 + m.a;
  return 2 * m.C1 * l + 4 * m.C2 * l * s * s + 2 * m.a * l * s * s * s * s - 2 * K / l;
}

TEST(Examples, UniaxialMooneyRivlinFollowsTheClosedFormAtEveryIncrement) {
  TempDir directory;
  const ExampleRun run = run_example("uniaxial-mooney-rivlin", directory);
  expect_complete_outputs(run);
  ASSERT_TRUE(run.report.success);

  const auto& spec = run.config.materials.at("rubber");
  const auto* params = std::get_if<material::MooneyRivlinParams>(&spec.base);
  ASSERT_NE(params, nullptr);
  const MooneyRivlin law{params->C1, params->C2, params->a};
  EXPECT_EQ(law.C1, 0.5);
  EXPECT_EQ(law.C2, 0.1);
  EXPECT_EQ(law.a, 2.0);
  // The block is 10 mm long; "pull" moves its far face by 5 mm along x (amplitude: a ramp).
  const double length = 10.0, end_displacement = 5.0, rest_area = 100.0;
  const auto stretch_at = [&](double lambda) { return 1.0 + lambda * end_displacement / length; };

  // Reaction force at every accepted step, against P(l) times the rest area.
  const auto steps = read_csv(run.output / "steps.csv");
  for (std::size_t i = 0; i < steps.rows.size(); ++i) {
    const double l = stretch_at(steps.at(i, "lambda"));
    const double s = lateral_stretch(law, l);
    const double expected = axial_nominal_stress(law, l, s) * rest_area;
    const double fx = steps.at(i, "pull.fx");
    EXPECT_NEAR(fx, expected, 1e-6 * std::abs(expected)) << "step " << i + 1 << ", stretch " << l;
    EXPECT_NEAR(steps.at(i, "pull.fy"), 0.0, 1e-9 * std::abs(expected));
    EXPECT_NEAR(steps.at(i, "pull.fz"), 0.0, 1e-9 * std::abs(expected));
    // The opposite face carries the opposite force.
    EXPECT_NEAR(steps.at(i, "x0.fx"), -expected, 1e-6 * std::abs(expected)) << "step " << i + 1;
  }
  // The last step is the full stretch 1.5.
  {
    const double l = 1.5, s = lateral_stretch(law, l);
    const double expected = axial_nominal_stress(law, l, s) * rest_area;
    std::printf("[ example  ] uniaxial: l = 1.5, s = %.10f, P A = %.10f N, pull.fx = %.10f N\n", s, expected,
                steps.rows.back()[steps.index("pull.fx")]);
    EXPECT_NEAR(steps.rows.back()[steps.index("pull.fx")], expected, 1e-6 * expected);
  }

  // Every node of every increment's VTU at x = (l X, s Y, s Z).
  const auto pvd = read_pvd(run.output / "sinew.pvd");
  ASSERT_EQ(pvd.size(), 6u);
  for (const auto& entry : pvd) {
    const double l = stretch_at(entry.time);
    const double s = lateral_stretch(law, l);
    const VtuState state = read_vtu_state(run.output / entry.file);
    const Eigen::MatrixXd X = state.rest();
    ASSERT_GT(X.rows(), 8);
    EXPECT_NEAR(X.col(0).maxCoeff(), 10.0, 1e-9);
    double worst = 0;
    Eigen::Index worst_node = -1;
    for (Eigen::Index v = 0; v < X.rows(); ++v) {
      const Eigen::Vector3d expected(l * X(v, 0), s * X(v, 1), s * X(v, 2));
      const double error = (state.x.row(v).transpose() - expected).cwiseAbs().maxCoeff();
      if (error > worst) {
        worst = error;
        worst_node = v;
      }
    }
    EXPECT_LE(worst, 1e-6) << entry.file << ": stretch " << l << ", lateral " << s << ", worst node " << worst_node
                           << " at rest (" << X.row(std::max<Eigen::Index>(worst_node, 0)) << ")";
  }
}

// ---------------------------------------------------------------------------------------------
// cantilever-gravity

TEST(Examples, CantileverGravityCarriesItsWeightAndSagsAsRecorded) {
  TempDir directory;
  const ExampleRun run = run_example("cantilever-gravity", directory);
  expect_complete_outputs(run);
  ASSERT_TRUE(run.report.success);

  // 0.5 x 0.05 x 0.05 m of rubber at 1000 kg/m^3 under g = 9.81 m/s^2.
  const double density = 1000, length = 0.5, side = 0.05, g = 9.81;
  const double weight = density * length * side * side * g;
  const auto steps = read_csv(run.output / "steps.csv");
  const double clamp_fz = steps.rows.back()[steps.index("clamp.fz")];
  EXPECT_NEAR(clamp_fz, weight, 1e-8 * weight) << "the clamp holds the bar's weight";
  EXPECT_NEAR(steps.rows.back()[steps.index("clamp.fx")], 0.0, 1e-6 * weight);
  EXPECT_NEAR(steps.rows.back()[steps.index("clamp.fy")], 0.0, 1e-6 * weight);
  // Gravity is ramped: at every step the clamp holds lambda times the weight.
  for (std::size_t i = 0; i < steps.rows.size(); ++i) {
    EXPECT_NEAR(steps.at(i, "clamp.fz"), steps.at(i, "lambda") * weight, 1e-8 * weight) << "step " << i + 1;
  }

  // Tip deflection: mean vertical displacement of the free end face (largest rest x).
  const auto pvd = read_pvd(run.output / "sinew.pvd");
  const VtuState state = read_vtu_state(run.output / pvd.back().file);
  const Eigen::MatrixXd X = state.rest();
  const double x_max = X.col(0).maxCoeff();
  EXPECT_NEAR(x_max, length, 1e-9);
  double sum = 0;
  int count = 0;
  for (Eigen::Index v = 0; v < X.rows(); ++v) {
    if (X(v, 0) >= x_max - 1e-9) {
      sum += state.u(v, 2);
      ++count;
    }
  }
  ASSERT_GT(count, 0);
  const double tip_deflection = -sum / count;

  // Euler-Bernoulli small-deflection estimate w = q L^4 / (8 E I), with the law's initial
  // moduli mu = 2 (C1 + C2), lambda = 4 (C2 + a) (logged for comparison, not asserted).
  const auto& mr = std::get<material::MooneyRivlinParams>(run.config.materials.at("rubber").base);
  const double mu = 2 * (mr.C1 + mr.C2), lame = 4 * (mr.C2 + mr.a);
  const double young = mu * (3 * lame + 2 * mu) / (lame + mu);
  const double q = density * g * side * side, inertia = side * side * side * side / 12;
  const double euler_bernoulli = q * std::pow(length, 4) / (8 * young * inertia);
  std::printf("[ example  ] cantilever: weight %.10g N, clamp.fz %.10g N, tip deflection %.8g m "
              "(%d end nodes), Euler-Bernoulli small-deflection estimate %.6g m (E = %.6g Pa)\n",
              weight, clamp_fz, tip_deflection, count, euler_bernoulli, young);

  // Recorded from this example (0.167927 m). It is 22 % below the inextensible elastica
  // (0.2152 m for q L^3 / (E I) = 4.07): linear tets four across the thickness, at Poisson's
  // ratio 0.45, are too stiff in bending; halving the element size gives 0.2004 m.
  constexpr double kRecordedTipDeflection = 0.167927;  // m
  EXPECT_NEAR(tip_deflection, kRecordedTipDeflection, 1e-4 * kRecordedTipDeflection);
  // Sanity: a large deflection, below the linear estimate (the bar curls, shortening its reach).
  EXPECT_GT(tip_deflection, 0.1 * length);
  EXPECT_LT(tip_deflection, euler_bernoulli);
}

// ---------------------------------------------------------------------------------------------
// twisted-cylinder

TEST(Examples, TwistedCylinderTorqueBalancesAndStiffens) {
  TempDir directory;
  const ExampleRun run = run_example("twisted-cylinder", directory);
  expect_complete_outputs(run);
  ASSERT_TRUE(run.report.success);

  const auto steps = read_csv(run.output / "steps.csv");
  const std::size_t last = steps.rows.size() - 1;
  const double torque = steps.at(last, "twist.mz");
  std::printf("[ example  ] twisted-cylinder: twist.mz %.10g, base.mz %.10g, twist.fz %.10g, base.fz %.10g "
              "(mN mm, mN)\n",
              torque, steps.at(last, "base.mz"), steps.at(last, "twist.fz"), steps.at(last, "base.fz"));

  // Equal and opposite reactions (both moments are about points on the z axis).
  for (std::size_t i = 0; i < steps.rows.size(); ++i) {
    const double scale = 1e-6 * std::abs(steps.at(i, "twist.mz"));
    for (const char* c : {"fx", "fy", "fz"}) {
      EXPECT_NEAR(steps.at(i, std::string("base.") + c) + steps.at(i, std::string("twist.") + c), 0.0, scale)
          << c << " at step " << i + 1;
    }
    EXPECT_NEAR(steps.at(i, "base.mz") + steps.at(i, "twist.mz"), 0.0, scale) << "mz at step " << i + 1;
  }

  // Recorded from this example. Linear theory, G J theta / L with G = alpha beta = 112 kPa, gives
  // 69 085 mN mm; the torque per degree at the first step (983) is 28 % above linear theory's
  // 768 (linear tets at Poisson's ratio 0.487 are stiff), the rest is the exponential stiffening.
  constexpr double kRecordedTorque = 119623.6;  // mN mm
  EXPECT_NEAR(torque, kRecordedTorque, 1e-4 * std::abs(kRecordedTorque));

  // The support turning the top by +90 degrees applies a positive torque that grows with the
  // angle, and faster than linearly: the exponential law stiffens.
  const double degrees_per_lambda = 90.0;
  for (std::size_t i = 0; i < steps.rows.size(); ++i) {
    const double previous = i == 0 ? 0.0 : steps.at(i - 1, "twist.mz");
    EXPECT_GT(steps.at(i, "twist.mz"), previous) << "torque not growing at step " << i + 1;
  }
  ASSERT_GE(steps.rows.size(), 2u);
  const double start_rate = steps.at(0, "twist.mz") / (degrees_per_lambda * steps.at(0, "lambda"));
  const double end_rate = (steps.at(last, "twist.mz") - steps.at(last - 1, "twist.mz")) /
                          (degrees_per_lambda * (steps.at(last, "lambda") - steps.at(last - 1, "lambda")));
  std::printf("[ example  ] twisted-cylinder: torque per degree %.6g at the start, %.6g at the end\n", start_rate,
              end_rate);
  EXPECT_GT(end_rate, start_rate);
}

// ---------------------------------------------------------------------------------------------
// compressed-block

TEST(Examples, CompressedBlockBalancesBulgesAndStiffens) {
  TempDir directory;
  const ExampleRun run = run_example("compressed-block", directory);
  expect_complete_outputs(run);
  ASSERT_TRUE(run.report.success);

  const auto steps = read_csv(run.output / "steps.csv");
  const std::size_t last = steps.rows.size() - 1;
  const double top_fz = steps.at(last, "top.fz");
  std::printf("[ example  ] compressed-block: top.fz %.10g N, bottom.fz %.10g N\n", top_fz,
              steps.at(last, "bottom.fz"));

  for (std::size_t i = 0; i < steps.rows.size(); ++i) {
    EXPECT_NEAR(steps.at(i, "top.fz") + steps.at(i, "bottom.fz"), 0.0, 1e-6 * std::abs(steps.at(i, "top.fz")))
        << "step " << i + 1;
  }

  // Recorded from this example; a bonded block of shape factor 0.5 at 30 % compression, about
  // 1.5 times the 582 N of a frictionless incompressible Mooney-Rivlin block.
  constexpr double kRecordedTopForce = -871.1987;  // N
  EXPECT_NEAR(top_fz, kRecordedTopForce, 1e-4 * std::abs(kRecordedTopForce));

  // The top plate pushes down (negative z force on the block), harder as it goes down.
  for (std::size_t i = 0; i < steps.rows.size(); ++i) {
    const double previous = i == 0 ? 0.0 : steps.at(i - 1, "top.fz");
    EXPECT_LT(steps.at(i, "top.fz"), previous) << "compression force not growing at step " << i + 1;
  }

  // The free sides bulge out past the rest faces x = 0 and x = 20.
  const auto pvd = read_pvd(run.output / "sinew.pvd");
  const VtuState state = read_vtu_state(run.output / pvd.back().file);
  const double bulge = (state.x.col(0).array() - 10.0).abs().maxCoeff();
  std::printf("[ example  ] compressed-block: largest |x - 10| = %.6g mm\n", bulge);
  EXPECT_GT(bulge, 10.0);
  // And the top face is where the plate put it.
  const Eigen::MatrixXd X = state.rest();
  for (Eigen::Index v = 0; v < X.rows(); ++v) {
    if (std::abs(X(v, 2) - 10.0) <= 1e-6) {
      EXPECT_NEAR(state.x(v, 2), 7.0, 1e-9) << "top node " << v;
    }
  }
}

}  // namespace
}  // namespace sinew::examples_test
