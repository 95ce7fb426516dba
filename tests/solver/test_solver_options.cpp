/// @file test_solver_options.cpp
/// Solver options beyond the defaults, each checked against a closed form or a static solution:
/// the two-point predictor, the residual line-search rule, quasi-viscosity and the quasistatic
/// integrator.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "sinew/fem/mass_matrix.hpp"
#include "sinew/fem/quadratic_energy.hpp"
#include "sinew/mesh/tet_mesh.hpp"
#include "sinew/solver/time_stepping.hpp"
#include "sinew/solver/load_stepping.hpp"
#include "support/problem_builder.hpp"
#include "support/solver_rig.hpp"

using namespace sinew;
namespace st = sinew::testing;

namespace {

using Predictor = solver::LoadSteppingOptions::Predictor;
using LineSearchRule = solver::NewtonOptions::LineSearchRule;

using st::kA;
using st::kC1;
using st::kC2;
using st::kUnitCube;

/// Largest distance of a node from the homogeneous uniaxial state F = diag(l, s, s) (l the
/// prescribed stretch, s the closed-form lateral stretch).
double distance_from_closed_form(const fem::Problem& problem, const Positions& x, double l) {
  const double s = st::mooney_rivlin_uniaxial(kC1, kC2, kA, l).first;
  double worst = 0;
  for (Index v = 0; v < x.rows(); ++v) {
    const Vector3 X = problem.mesh.rest.row(v).transpose();
    worst = std::max(worst, (x.row(v).transpose() - Vector3(l * X.x(), s * X.y(), s * X.z())).norm());
  }
  return worst;
}

/// Tight tolerances: the converged states agree with the closed form to round-off.
solver::StaticSolverOptions tight_options(int increments, Predictor predictor) {
  solver::StaticSolverOptions options;
  options.stepping.increments = increments;
  options.stepping.predictor = predictor;
  options.newton.residual_tolerance = 1e-12;
  options.newton.increment_tolerance = 1e-12;
  return options;
}

/// What a static run did, step by step.
struct StaticTrace {
  solver::StepperResult result;
  std::vector<double> lateral;       ///< s after each accepted step (s = 1 at lambda = 0)
  std::vector<double> lambda;        ///< lambda after each accepted step (0 first)
  std::map<int, double> start_energy;    ///< per step: Pi at the Newton start (iteration 0)
  std::map<int, double> start_residual;  ///< per step: |g_q| at the Newton start
  /// Iterations (of any attempt, failed ones included) whose residual exceeds the one before.
  int residual_increases = 0;
};

/// Solves uniaxial tension (stretch, Mooney-Rivlin kC1, kC2, kA) and checks the end state
/// against the closed form (1e-9) when the run succeeds.
StaticTrace run_uniaxial(double stretch, const solver::StaticSolverOptions& options,
                         const solver::NewtonSetup& setup = kUnitCube) {
  st::SolverRig rig(st::uniaxial_problem(stretch, kC1, kC2, kA));
  // The node at rest (1, 1, 1) sits at (l, s, s).
  Index corner = -1;
  for (Index v = 0; v < rig.problem.mesh.num_nodes(); ++v)
    if ((rig.problem.mesh.rest.row(v) - Eigen::RowVector3d(1, 1, 1)).norm() < 1e-12) corner = v;
  StaticTrace trace;
  trace.lateral.push_back(1.0);
  trace.lambda.push_back(0.0);
  solver::StepperCallbacks callbacks;
  double last_residual = 0;
  callbacks.on_iteration = [&](const solver::StepRecord& step, const solver::IterationRecord& it) {
    if (it.iteration > 0 && it.residual > last_residual) ++trace.residual_increases;
    last_residual = it.residual;
    if (step.step == 0 || it.iteration > 0) return;
    // Overwritten when a cut step is retried: the accepted attempt's start remains.
    trace.start_energy[step.step] = it.energy;
    trace.start_residual[step.step] = it.residual;
  };
  callbacks.on_step = [&](const solver::StepRecord& step, const fem::State& state, const NodalVectors&) {
    trace.lateral.push_back(state.x(corner, 1));
    trace.lambda.push_back(step.t);
  };
  trace.result = solver::solve_static(*rig.objective, options, setup, callbacks);
  if (trace.result.success) {
    EXPECT_LT(distance_from_closed_form(rig.problem, trace.result.last_state.x, stretch), 1e-9);
  }
  return trace;
}

}  // namespace

// The two-point predictor starts step k at the linear extrapolation of the states after steps
// k-2 and k-1. Uniaxial tension stays homogeneous, so that start is F = diag(l_k, s_e, s_e) with
// s_e = s_{k-1} + r (s_{k-1} - s_{k-2}), r the ratio of the step sizes: the energy and residual
// Newton reports at that start must be those of this state.
TEST(SolverOptions, TwoPointPredictorStartsAtTheLinearExtrapolationAndReachesTheClosedForm) {
  const double stretch = 1.6;
  const StaticTrace none = run_uniaxial(stretch, tight_options(4, Predictor::None));
  const StaticTrace two_point = run_uniaxial(stretch, tight_options(4, Predictor::TwoPoint));
  const StaticTrace tangent = run_uniaxial(stretch, tight_options(4, Predictor::Tangent));
  ASSERT_TRUE(none.result.success) << none.result.message;
  ASSERT_TRUE(two_point.result.success) << two_point.result.message;
  ASSERT_TRUE(tangent.result.success) << tangent.result.message;
  // The same answer as the tangent predictor (and the closed form, checked in run_uniaxial).
  EXPECT_LT((two_point.result.last_state.x - tangent.result.last_state.x).cwiseAbs().maxCoeff(), 1e-10);
  // Step 1 has no earlier step to extrapolate from: it starts where Predictor::None does.
  EXPECT_EQ(two_point.start_residual.at(1), none.start_residual.at(1));

  st::SolverRig probe(st::uniaxial_problem(stretch, kC1, kC2, kA));
  const auto& lambda = two_point.lambda;
  ASSERT_GE(lambda.size(), 4u);
  for (std::size_t k = 2; k < lambda.size(); ++k) {
    const double r = (lambda[k] - lambda[k - 1]) / (lambda[k - 1] - lambda[k - 2]);
    const double l = 1 + (stretch - 1) * lambda[k];
    const double s = two_point.lateral[k - 1] + r * (two_point.lateral[k - 1] - two_point.lateral[k - 2]);
    fem::State start = probe.dofs->initial_state(lambda[k]);
    start.x = probe.problem.mesh.rest * Vector3(l, s, s).asDiagonal();
    probe.objective->set_load_parameter(lambda[k]);
    const double energy = probe.objective->value(start);
    const double residual = probe.dofs->reduce_gradient(start, probe.objective->full_gradient(start)).norm();
    const int step = static_cast<int>(k);
    EXPECT_NEAR(two_point.start_energy.at(step), energy, 1e-12 * std::abs(energy)) << "step " << step;
    EXPECT_NEAR(two_point.start_residual.at(step), residual, 1e-9 * residual) << "step " << step;
    // The extrapolated start is closer to equilibrium than the last state (Predictor::None):
    // measured 0.073, 0.066, 0.059 against 1.36, 1.19, 1.07 at steps 2, 3, 4.
    EXPECT_LT(two_point.start_residual.at(step), 0.2 * none.start_residual.at(step)) << "step " << step;
  }
  // Measured: 14 Newton iterations against 20 without a predictor (12 with the tangent one).
  EXPECT_LT(two_point.result.newton_iterations, none.result.newton_iterations);
}

// The residual rule accepts a step only when |g_q| decreases. Compression to half the length in
// one increment: the energy rule takes a step that raises the residual (6.8 -> 7.1 at the first
// iteration); the residual rule halves that step instead, and every iteration, of every attempt,
// lowers the residual. Both reach the closed form.
TEST(SolverOptions, ResidualLineSearchDecreasesTheResidualAtEveryIterationAndReachesTheClosedForm) {
  const double stretch = 0.5;
  solver::StaticSolverOptions options = tight_options(1, Predictor::None);
  const StaticTrace energy_rule = run_uniaxial(stretch, options);
  options.newton.line_search = LineSearchRule::Residual;
  const StaticTrace residual_rule = run_uniaxial(stretch, options);
  ASSERT_TRUE(energy_rule.result.success) << energy_rule.result.message;
  ASSERT_TRUE(residual_rule.result.success) << residual_rule.result.message;
  EXPECT_GE(energy_rule.residual_increases, 1);
  EXPECT_EQ(residual_rule.residual_increases, 0);
  EXPECT_LT((residual_rule.result.last_state.x - energy_rule.result.last_state.x).cwiseAbs().maxCoeff(),
            1e-10);
}

namespace {

/// Quasi-viscosity per node as model::build_model builds it (src/sinew/model/model.cpp):
/// D_a = eta * (volume of the tets around node a)^(1/3).
VectorX node_viscosity(const mesh::TetMesh& mesh, double eta) {
  VectorX volume = VectorX::Zero(mesh.num_nodes());
  for (Index t = 0; t < mesh.num_tets(); ++t) {
    const double v = std::abs(mesh::signed_volume(mesh.rest, mesh.tets, t));
    for (int i = 0; i < 4; ++i) volume[mesh.tets(t, i)] += v;
  }
  return eta * volume.unaryExpr([](double v) { return std::cbrt(v); });
}

}  // namespace

// Quasi-viscosity adds D/dt to the tangent only: it changes the Newton path (more, shorter
// iterations), not the equilibrium.
TEST(SolverOptions, QuasiViscosityChangesTheNewtonPathButNotTheEquilibrium) {
  const double stretch = 1.6;
  solver::StaticSolverOptions options = tight_options(4, Predictor::Tangent);
  options.newton.max_iterations = 100;
  const StaticTrace plain = run_uniaxial(stretch, options);
  solver::NewtonSetup viscous = kUnitCube;
  viscous.node_viscosity = node_viscosity(st::uniaxial_problem(stretch, kC1, kC2, kA).mesh, 0.1);
  const StaticTrace damped = run_uniaxial(stretch, options, viscous);
  ASSERT_TRUE(plain.result.success) << plain.result.message;
  ASSERT_TRUE(damped.result.success) << damped.result.message;
  // Both match the closed form (run_uniaxial) and each other.
  EXPECT_LT((damped.result.last_state.x - plain.result.last_state.x).cwiseAbs().maxCoeff(), 1e-10);
  // Measured: 40 Newton iterations against 12: the viscous term shortens every step.
  EXPECT_GT(damped.result.newton_iterations, plain.result.newton_iterations + 10);
}

// Quasistatic integration (viscosity, no inertia) of a clamped bar under gravity applied in full
// at t = 0: the bar creeps down and settles at the static solution.
TEST(SolverOptions, QuasistaticIntegrationSettlesAtTheStaticSolution) {
  auto bar = [] {
    auto p = st::box_problem(8, 2, 2, Vector3(0, 0, 0), Vector3(4, 1, 1), st::mooney_rivlin(10, 2, 50), 1.0);
    p.gravity = Vector3(0, 0, -1);
    p.prescribed.push_back({"clamp", st::nodes_on_plane(p.mesh, 0, 0.0), fem::RigidMotion{}});
    return p;
  };
  st::SolverRig statics(bar());
  solver::StaticSolverOptions options;
  options.stepping.increments = 2;
  options.newton.residual_tolerance = 1e-10;
  const auto reference = solver::solve_static(*statics.objective, options, {.characteristic_length = 4.0, .reference_force = 16.0});
  ASSERT_TRUE(reference.success) << reference.message;
  const double static_tip = reference.last_state.x.col(2).minCoeff();

  // D = c M, M the lumped mass matrix; gravity in full from t = 0 as in the command line.
  const fem::Problem p = bar();
  const double damping = 1.0;
  fem::QuadraticEnergy viscosity(
      "viscosity", fem::block_mass_matrix(damping * fem::mass_matrix(p.mesh.rest, p.mesh.tets, p.mesh.region,
                                                                     p.region_density, fem::MassKind::Lumped)));
  st::SolverRig run(bar(), {}, fem::Amplitude{{{0.0, 1.0}}}, {&viscosity});
  solver::DynamicOptions dynamics;
  dynamics.integrator = solver::DynamicOptions::Integrator::Quasistatic;
  dynamics.end_time = 100;
  dynamics.output_interval = 10;
  std::vector<double> tips;
  solver::StepperCallbacks callbacks;
  callbacks.on_step = [&](const solver::StepRecord& step, const fem::State& state, const NodalVectors&) {
    if (step.step > 0) tips.push_back(state.x.col(2).minCoeff());
  };
  const auto result = solver::solve_dynamic(*run.objective, {.inertia = nullptr, .viscosity = &viscosity}, dynamics,
                                            options, {.characteristic_length = 4.0, .reference_force = 16.0}, {}, callbacks);
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_NEAR(result.t, dynamics.end_time, 1e-12);
  // The path is viscous: the first step (h = 1) reaches about 40 % of the static sag (measured
  // tip -0.79 against -1.93), and the tip then creeps down without overshooting.
  ASSERT_GE(tips.size(), 2u);
  EXPECT_GT(tips.front(), 0.6 * static_tip);
  for (std::size_t k = 1; k < tips.size(); ++k) EXPECT_LE(tips[k], tips[k - 1] + 1e-9) << "step " << k + 1;
  // At t = 100 (the first step suggests a relaxation time near 1.5) it is the static solution:
  // measured largest node distance 1.0e-9.
  EXPECT_LT((result.last_state.x - reference.last_state.x).rowwise().norm().maxCoeff(), 1e-7);
}
