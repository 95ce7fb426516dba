#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sinew/fem/elastic_energy.hpp"
#include "sinew/fem/external_force_energy.hpp"
#include "sinew/fem/reactions.hpp"
#include "sinew/solver/load_stepping.hpp"
#include "support/problem_builder.hpp"
#include "support/solver_rig.hpp"

using namespace sinew;
namespace st = sinew::testing;

using st::mooney_rivlin_uniaxial;
using st::SolverRig;
using st::uniaxial_problem;

TEST(StaticSolver, UniaxialMooneyRivlinMatchesClosedForm) {
  const double C1 = 0.5, C2 = 0.2, a = 1.5, stretch = 1.6;
  SolverRig run(uniaxial_problem(stretch, C1, C2, a));
  solver::StaticSolverOptions options;
  options.stepping.increments = 4;
  options.newton.residual_tolerance = 1e-12;
  options.newton.increment_tolerance = 1e-12;
  const auto result = solver::solve_static(*run.objective, options, {.characteristic_length = std::sqrt(3.0), .reference_force = 1.0});
  ASSERT_TRUE(result.success) << result.message;

  const auto [s, axial] = mooney_rivlin_uniaxial(C1, C2, a, stretch);
  const auto& x = result.last_state.x;
  for (Index v = 0; v < x.rows(); ++v) {
    const Vector3 X = run.problem.mesh.rest.row(v).transpose();
    EXPECT_NEAR(x(v, 0), stretch * X.x(), 1e-9);
    EXPECT_NEAR(x(v, 1), s * X.y(), 1e-9);
    EXPECT_NEAR(x(v, 2), s * X.z(), 1e-9);
  }
  const auto g = run.objective->full_gradient(result.last_state);
  const auto reactions = fem::compute_reactions(run.problem, *run.dofs, result.last_state, g);
  // "pull" holds the x = 1 face: its force on the body is the nominal stress times the unit rest
  // area, pulling in +x; "x0" pulls the other way.
  const double force = reactions[3].force.x();
  EXPECT_NEAR(force / axial, 1.0, 1e-6) << "FE force " << force << " closed form " << axial;
  EXPECT_NEAR(reactions[0].force.x() / -axial, 1.0, 1e-6);
}

TEST(StaticSolver, PatchTestOnADistortedMeshReproducesTheHomogeneousState) {
  // The uniaxial setup on a mesh whose interior nodes are moved off the grid: linear tets must
  // reproduce the homogeneous solution exactly, whatever their shapes.
  const double C1 = 0.8, C2 = 0.1, a = 2.0, stretch = 0.75;
  fem::Problem p = uniaxial_problem(stretch, C1, C2, a);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.08, 0.08);
  for (Index v = 0; v < p.mesh.num_nodes(); ++v) {
    const auto X = p.mesh.rest.row(v);
    if (X.minCoeff() > 1e-12 && X.maxCoeff() < 1 - 1e-12)
      for (int k = 0; k < 3; ++k) p.mesh.rest(v, k) += u(rng);
  }
  SolverRig run(std::move(p));
  solver::StaticSolverOptions options;
  options.stepping.increments = 3;
  options.newton.residual_tolerance = 1e-12;
  const auto result = solver::solve_static(*run.objective, options, {.characteristic_length = 1.0, .reference_force = 1.0});
  ASSERT_TRUE(result.success) << result.message;
  const double s = mooney_rivlin_uniaxial(C1, C2, a, stretch).first;
  for (Index v = 0; v < run.problem.mesh.num_nodes(); ++v) {
    const Vector3 X = run.problem.mesh.rest.row(v).transpose();
    EXPECT_NEAR((result.last_state.x.row(v).transpose() - Vector3(stretch * X.x(), s * X.y(), s * X.z())).norm(), 0,
                1e-9);
  }
}

TEST(StaticSolver, RigidBoundaryMotionMovesTheInteriorRigidly) {
  auto p = st::box_problem(3, 3, 3, Vector3(0, 0, 0), Vector3(1, 1, 1), st::mooney_rivlin(1.0, 0.5, 3.0));
  std::vector<Index> boundary;
  for (Index v = 0; v < p.mesh.num_nodes(); ++v) {
    const auto X = p.mesh.rest.row(v);
    if (X.minCoeff() < 1e-12 || X.maxCoeff() > 1 - 1e-12) boundary.push_back(v);
  }
  fem::RigidMotion motion;
  motion.angle = 1.2;
  motion.axis = Vector3(1, 2, 2);
  motion.axis_point = Vector3(0.5, 0.5, 0.5);
  motion.translation = Vector3(0.3, 0, -0.2);
  p.prescribed.push_back({"boundary", boundary, motion});
  SolverRig run(std::move(p));
  solver::StaticSolverOptions options;
  options.stepping.increments = 3;
  options.newton.residual_tolerance = 1e-10;
  const auto result = solver::solve_static(*run.objective, options, {.characteristic_length = 1.0, .reference_force = 1.0});
  ASSERT_TRUE(result.success) << result.message;
  for (Index v = 0; v < run.problem.mesh.num_nodes(); ++v) {
    const Vector3 expected = motion.apply(run.problem.mesh.rest.row(v).transpose(), 1.0);
    EXPECT_NEAR((result.last_state.x.row(v).transpose() - expected).norm(), 0, 1e-8);
  }
}

TEST(StaticSolver, NewtonConvergesQuadraticallyOnASmoothCase) {
  SolverRig run(uniaxial_problem(1.3, 0.5, 0.2, 1.5));
  solver::StaticSolverOptions options;
  options.stepping.increments = 1;
  options.stepping.predictor = solver::LoadSteppingOptions::Predictor::None;
  options.newton.residual_tolerance = 1e-13;
  options.newton.increment_tolerance = 0;
  // Exact Newton: a factorization per iteration (lagged CG is inexact by design while the
  // residual is far from the tolerance, docs/solver.md).
  options.linear.lagged_iterations = 0;
  std::vector<double> residuals;
  solver::StepperCallbacks callbacks;
  callbacks.on_iteration = [&](const solver::StepRecord& step, const solver::IterationRecord& it) {
    if (step.step == 1) residuals.push_back(it.residual / it.force_scale);
  };
  const auto result = solver::solve_static(*run.objective, options, {.characteristic_length = 1.0, .reference_force = 1.0}, callbacks);
  ASSERT_TRUE(result.success) << result.message;
  ASSERT_GE(residuals.size(), 4u);
  // Once in the quadratic regime, r_{k+1} <= C r_k^2: check the last ratios that are above round-off.
  int quadratic_steps = 0;
  for (std::size_t k = 1; k < residuals.size(); ++k) {
    if (residuals[k - 1] < 1e-2 && residuals[k] > 1e-13) {
      EXPECT_LT(residuals[k], 10 * residuals[k - 1] * residuals[k - 1]) << "iteration " << k;
      ++quadratic_steps;
    }
  }
  EXPECT_GE(quadratic_steps, 1);
}

class LinearSolverKinds : public ::testing::TestWithParam<solver::LinearSolverOptions::Kind> {};

TEST_P(LinearSolverKinds, GravitySagOfAClampedBarAgrees) {
  auto p = st::box_problem(8, 2, 2, Vector3(0, 0, 0), Vector3(4, 1, 1), st::mooney_rivlin(10, 2, 50), 1.0);
  p.gravity = Vector3(0, 0, -1);
  p.prescribed.push_back({"clamp", st::nodes_on_plane(p.mesh, 0, 0.0), fem::RigidMotion{}});
  SolverRig run(std::move(p));
  solver::StaticSolverOptions options;
  options.linear.kind = GetParam();
  options.linear.tolerance = GetParam() == solver::LinearSolverOptions::Kind::Gmres ? 0.1 : 1e-3;
  options.linear.max_iterations = 300;
  options.stepping.increments = 2;
  options.newton.max_iterations = 200;
  options.newton.residual_tolerance = 1e-8;
  const auto result = solver::solve_static(*run.objective, options, {.characteristic_length = 4.0, .reference_force = 16.0});
  ASSERT_TRUE(result.success) << result.message;
  // Tip deflection of the reference (CHOLMOD, tight tolerance) run.
  static double reference = 0;
  const double tip = result.last_state.x.col(2).minCoeff();
  if (GetParam() == solver::LinearSolverOptions::Kind::Cholmod) reference = tip;
  EXPECT_LT(tip, -0.01);
  if (reference != 0) {
    EXPECT_NEAR(tip, reference, 1e-6 * std::abs(reference) + 1e-9);
  }
}

INSTANTIATE_TEST_SUITE_P(All, LinearSolverKinds,
                         ::testing::Values(solver::LinearSolverOptions::Kind::Cholmod,
                                           solver::LinearSolverOptions::Kind::Gmres,
                                           solver::LinearSolverOptions::Kind::ConjugateGradient));

TEST(StaticSolver, ImpossibleMotionFailsClearlyAndKeepsTheLastConvergedState) {
  // Crush a block to zero thickness: the last increment cannot exist without inversion.
  auto p = st::box_problem(2, 2, 2, Vector3(0, 0, 0), Vector3(1, 1, 1), st::mooney_rivlin());
  p.prescribed.push_back({"floor", st::nodes_on_plane(p.mesh, 2, 0.0), fem::RigidMotion{}});
  fem::RigidMotion crush;
  crush.translation = Vector3(0, 0, -1.0);
  p.prescribed.push_back({"press", st::nodes_on_plane(p.mesh, 2, 1.0), crush});
  SolverRig run(std::move(p));
  solver::StaticSolverOptions options;
  options.stepping.increments = 4;
  options.stepping.min_step = 1e-3;
  const auto result = solver::solve_static(*run.objective, options, {.characteristic_length = 1.0, .reference_force = 1.0});
  EXPECT_FALSE(result.success);
  EXPECT_NE(result.message.find("could not be solved"), std::string::npos) << result.message;
  EXPECT_NE(result.message.find("last converged"), std::string::npos) << result.message;
  EXPECT_GE(result.segments_completed, 2);
  EXPECT_LT(result.segments_completed, 4);
  EXPECT_TRUE(run.objective->is_valid(result.last_state));
  EXPECT_GT(result.last_state.lambda, 0.5);
}

TEST(StaticSolver, FreeRigidBodyHangingFromASoftBlockCarriesItsWeight) {
  // A soft column clamped at the top with a heavy free rigid block bonded below it.
  auto p = st::box_problem(2, 2, 6, Vector3(0, 0, 0), Vector3(1, 1, 3), st::mooney_rivlin(5, 1, 20), 1.0);
  st::add_rigid_region(p, "weight", fem::RigidBody::Kind::Free, 20.0, [](const Vector3& c) { return c.z() < 1.0; });
  p.gravity = Vector3(0, 0, -1);
  p.prescribed.push_back({"ceiling", st::nodes_on_plane(p.mesh, 2, 3.0), fem::RigidMotion{}});
  SolverRig run(std::move(p));
  solver::StaticSolverOptions options;
  options.stepping.increments = 2;
  options.newton.residual_tolerance = 1e-10;
  const auto result =
      solver::solve_static(*run.objective, options, {.characteristic_length = 3.0, .reference_force = 90.0});
  ASSERT_TRUE(result.success) << result.message;
  const auto g = run.objective->full_gradient(result.last_state);
  const auto reactions = fem::compute_reactions(run.problem, *run.dofs, result.last_state, g);
  const double total_weight = (1.0 * 2.0 + 20.0 * 1.0) * 1.0;  // soft: 2 volume units, weight: 1
  EXPECT_NEAR(reactions[0].force.z(), total_weight, 1e-8 * total_weight);
  EXPECT_LT(reactions[1].force.norm(), 1e-8 * total_weight);  // a free body needs no support
  // The weight moved down.
  const auto& pose = result.last_state.rigid[0];
  EXPECT_LT(pose.t.z(), -1e-3);
  // Compare with the same weight made of a very stiff deformable material: the free rigid body
  // must behave as its stiff limit (the tilt comes from the mesh's diagonal, the same in both).
  auto q = st::box_problem(2, 2, 6, Vector3(0, 0, 0), Vector3(1, 1, 3), st::mooney_rivlin(5, 1, 20), 1.0);
  q.mesh.region = run.problem.mesh.region;
  q.mesh.region_names = {"soft", "weight"};
  q.region_material.push_back(st::mooney_rivlin(5e3, 1e3, 2e4));  // 1000x stiffer
  q.region_density.push_back(20.0);
  q.gravity = Vector3(0, 0, -1);
  q.prescribed.push_back({"ceiling", st::nodes_on_plane(q.mesh, 2, 3.0), fem::RigidMotion{}});
  SolverRig stiff(std::move(q));
  options.newton.residual_tolerance = 1e-9;
  const auto stiff_result =
      solver::solve_static(*stiff.objective, options, {.characteristic_length = 3.0, .reference_force = 90.0});
  ASSERT_TRUE(stiff_result.success) << stiff_result.message;
  for (Index a : run.dofs->rigid_members(0)) {
    const double gap = (result.last_state.x.row(a) - stiff_result.last_state.x.row(a)).norm();
    EXPECT_LT(gap, 1e-2 * std::abs(pose.t.z())) << "node " << a;
  }
}

namespace {

/// Every node in a tilted double well along x, stiff springs in y and z (u = x - rest):
/// E = sum_a k (u_x^4 / 4 - u_x^2 / 2) - f(lambda) u_x + k (u_y^2 + u_z^2) / 2 with
/// f(lambda) = k (-0.6 + 1.2 lambda). The left well, where every node starts, disappears at
/// f = 2 k / (3 sqrt 3) (lambda = 0.82): a limit point past which the only equilibrium is in
/// the right well, 2.4 away. No step size, however small, crosses it continuously.
class TiltedDoubleWell : public Energy {
 public:
  TiltedDoubleWell(Positions rest, double k) : rest_(std::move(rest)), k_(k) {}
  std::string_view name() const override { return "tilted double well"; }
  double tilt() const { return k_ * (-0.6 + 1.2 * lambda_); }
  double value(const Positions& x) const override {
    double e = 0;
    for (Index a = 0; a < x.rows(); ++a) {
      const Vector3 u = (x.row(a) - rest_.row(a)).transpose();
      e += k_ * (std::pow(u.x(), 4) / 4 - u.x() * u.x() / 2) - tilt() * u.x() + k_ * (u.y() * u.y() + u.z() * u.z()) / 2;
    }
    return e;
  }
  void add_gradient(const Positions& x, NodalVectors& grad) const override {
    for (Index a = 0; a < x.rows(); ++a) {
      const Vector3 u = (x.row(a) - rest_.row(a)).transpose();
      grad(a, 0) += k_ * (std::pow(u.x(), 3) - u.x()) - tilt();
      grad(a, 1) += k_ * u.y();
      grad(a, 2) += k_ * u.z();
    }
  }
  void add_hessian(const Positions& x, BlockSparseMatrix& H) const override {
    for (Index a = 0; a < x.rows(); ++a) {
      const double ux = x(a, 0) - rest_(a, 0);
      Matrix3 block = k_ * Matrix3::Identity();
      block(0, 0) = k_ * (3 * ux * ux - 1);
      H.add(H.find(a, a), block);
    }
  }
  void hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const override {
    for (Index a = 0; a < rest_.rows(); ++a) pairs.emplace_back(a, a);
  }
  void set_load_parameter(double lambda) override { lambda_ = lambda; }

 private:
  Positions rest_;
  double k_;
  double lambda_ = 0;
};

struct DoubleWellRig {
  fem::Problem problem = st::box_problem(1, 1, 1, Vector3(0, 0, 0), Vector3(1, 1, 1), st::mooney_rivlin());
  fem::DofMap dofs{problem};
  TiltedDoubleWell well{problem.mesh.rest, 10.0};
  solver::Objective objective{dofs, std::vector<Energy*>{&well}, problem.mesh.num_nodes()};
};

}  // namespace

TEST(StaticSolver, SnapThroughBudgetCarriesTheSolutionPastALimitPoint) {
  solver::StaticSolverOptions options;
  options.stepping.increments = 10;
  options.newton.max_iterations = 4;  // enough for every step but the snap
  options.newton.residual_tolerance = 1e-10;
  const solver::NewtonSetup setup{.characteristic_length = 1.0, .reference_force = 1.0};

  // Without the snap-through budget, halving never gets past the limit point.
  {
    DoubleWellRig rig;
    solver::StaticSolverOptions off = options;
    off.stepping.snap_through_after_cuts = 0;
    const auto result = solver::solve_static(rig.objective, off, setup);
    EXPECT_FALSE(result.success);
    EXPECT_EQ(result.snap_throughs, 0);
    EXPECT_NEAR(result.last_state.lambda, 0.82, 0.02) << "stuck at the limit point";
    EXPECT_NE(result.message.find("could not be solved"), std::string::npos) << result.message;
  }
  // With it (the default: after 2 failed attempts), the long attempt walks down into the right
  // well and the stepping goes on.
  DoubleWellRig rig;
  std::vector<double> snap_lambdas;
  solver::StepperCallbacks callbacks;
  callbacks.on_step = [&](const solver::StepRecord& step, const fem::State&, const NodalVectors&) {
    if (step.snap_through) snap_lambdas.push_back(step.t);
  };
  const auto result = solver::solve_static(rig.objective, options, setup, callbacks);
  ASSERT_TRUE(result.success) << result.message;
  // Near the fold Newton also slows down, so a step just before it may use the long budget too.
  ASSERT_GE(result.snap_throughs, 1);
  EXPECT_EQ(static_cast<int>(snap_lambdas.size()), result.snap_throughs);
  EXPECT_GT(snap_lambdas.back(), 0.82) << "the step across the limit point";
  EXPECT_NE(result.message.find(" snap-through"), std::string::npos) << result.message;
  // At lambda = 1 the tilt is 0.6 k: the single root of u^3 - u = 0.6, in the right well.
  double root = 1.2;
  for (int i = 0; i < 50; ++i) root -= (root * root * root - root - 0.6) / (3 * root * root - 1);
  const Positions u = result.last_state.x - rig.problem.mesh.rest;
  EXPECT_NEAR(u.col(0).minCoeff(), root, 1e-8);
  EXPECT_NEAR(u.col(0).maxCoeff(), root, 1e-8);
  EXPECT_LT(u.rightCols(2).cwiseAbs().maxCoeff(), 1e-10);
}

// solver.stabilization: with no snap-through budget the steps get stuck at the fold (above);
// with the pseudo-viscous term switched on there, the run goes on, crosses into the right well
// and ends next to the equilibrium at lambda = 1, reporting the steps and the energy it damped.
TEST(StaticSolver, StabilizationCarriesTheStepsPastALimitPointWhereTheyGetStuck) {
  DoubleWellRig rig;
  BlockSparseMatrix D;
  D.set_pattern(rig.problem.mesh.num_nodes(), {});
  const double damping = 0.05;  // against the well's stiffness k = 10
  for (Index a = 0; a < D.num_nodes(); ++a) D.add(D.find(a, a), damping * Matrix3::Identity());
  fem::QuadraticEnergy stabilization("stabilization", D);
  solver::Objective objective(rig.dofs, std::vector<Energy*>{&rig.well, &stabilization}, rig.problem.mesh.num_nodes());
  solver::StaticSolverOptions options;
  options.stepping.increments = 10;
  options.stepping.snap_through_after_cuts = 0;
  options.newton.max_iterations = 8;
  options.newton.residual_tolerance = 1e-10;
  const solver::NewtonSetup setup{.characteristic_length = 1.0, .reference_force = 1.0};

  std::vector<solver::StepRecord> steps;
  std::vector<double> potentials;             // of each accepted state, without the viscous term
  std::vector<double> equilibrium_residuals;  // of each step's last Newton iteration
  int stabilize_calls = 0;
  double stuck_at = 0;
  solver::Objective potential(rig.dofs, std::vector<Energy*>{&rig.well}, rig.problem.mesh.num_nodes());
  solver::StepperCallbacks callbacks;
  callbacks.on_step = [&](const solver::StepRecord& step, const fem::State& state, const NodalVectors&) {
    steps.push_back(step);
    potential.set_load_parameter(state.lambda);
    potentials.push_back(potential.value(state));
  };
  callbacks.on_iteration = [&](const solver::StepRecord& step, const solver::IterationRecord& it) {
    if (step.step == 0) return;  // the solve at lambda = 0
    if (static_cast<int>(equilibrium_residuals.size()) < step.step) equilibrium_residuals.resize(step.step);
    equilibrium_residuals[static_cast<std::size_t>(step.step - 1)] = it.equilibrium_residual;
  };
  callbacks.on_stabilize = [&](const solver::StepRecord& step, const std::string& why) {
    ++stabilize_calls;
    stuck_at = step.t - step.step_size;
    EXPECT_FALSE(why.empty());
  };
  const auto result = solver::solve_static(objective, options, setup, callbacks, nullptr, nullptr, &stabilization);
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_EQ(stabilize_calls, 1);
  EXPECT_NEAR(stuck_at, 0.82, 0.02) << "where the plain steps got stuck";
  EXPECT_EQ(result.snap_throughs, 0);
  ASSERT_GE(result.stabilized_steps, 1);
  // Steps before the fold are plain equilibria; every step after it is stabilized and damps.
  double dissipated = 0;
  int stabilized = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (steps[i].t < stuck_at + 1e-12) {
      EXPECT_EQ(steps[i].dissipated, 0.0) << "step " << steps[i].step;
      EXPECT_DOUBLE_EQ(equilibrium_residuals.at(i), steps[i].residual);
    } else {
      EXPECT_GT(steps[i].dissipated, 0.0) << "step " << steps[i].step;
      ++stabilized;
      // newton.csv's equilibrium residual leaves the viscous forces out.
      EXPECT_NE(equilibrium_residuals.at(i), steps[i].residual);
    }
    dissipated += steps[i].dissipated;
    // The step's energy (steps.csv) is the potential, without the viscous term.
    EXPECT_NEAR(steps[i].energy, potentials[i], 1e-9 * (1 + std::abs(potentials[i]))) << "step " << steps[i].step;
  }
  EXPECT_EQ(stabilized, result.stabilized_steps);
  EXPECT_NEAR(result.dissipated, dissipated, 1e-12 * dissipated);
  // Crossing from the left well to the right one (u from about -0.6 to 1.2 on 8 nodes) releases
  // energy, which the damping takes (77 here).
  EXPECT_GT(result.dissipated, 10.0);
  // At lambda = 1 the state lies in the right well near its root; the viscous forces that are
  // left (D times the last steps' rate of motion) keep it off by a little.
  double root = 1.2;
  for (int i = 0; i < 50; ++i) root -= (root * root * root - root - 0.6) / (3 * root * root - 1);
  const Positions u = result.last_state.x - rig.problem.mesh.rest;
  EXPECT_EQ(result.last_state.lambda, 1.0);
  EXPECT_NEAR(u.col(0).minCoeff(), root, 5e-3);  // 1.2207 against 1.2212
  EXPECT_NEAR(u.col(0).maxCoeff(), root, 5e-3);

  // With stabilization 0 (no term) the same steps stop at the fold.
  DoubleWellRig plain;
  const auto stopped = solver::solve_static(plain.objective, options, setup);
  EXPECT_FALSE(stopped.success);
  EXPECT_NEAR(stopped.last_state.lambda, stuck_at, 1e-12);
  EXPECT_EQ(stopped.stabilized_steps, 0);
}

// A stabilized run resumed from any accepted step (before the fold, and after the stabilization
// started) ends where the uninterrupted run ended, with the same counts and dissipated energy.
TEST(StaticSolver, AStabilizedRunResumesExactly) {
  auto run = [](const solver::StepperSnapshot* resume, std::vector<solver::StepperSnapshot>* snapshots) {
    DoubleWellRig rig;
    BlockSparseMatrix D;
    D.set_pattern(rig.problem.mesh.num_nodes(), {});
    for (Index a = 0; a < D.num_nodes(); ++a) D.add(D.find(a, a), 0.05 * Matrix3::Identity());
    fem::QuadraticEnergy stabilization("stabilization", D);
    solver::Objective objective(rig.dofs, std::vector<Energy*>{&rig.well, &stabilization},
                                rig.problem.mesh.num_nodes());
    solver::StaticSolverOptions options;
    options.stepping.increments = 10;
    options.stepping.snap_through_after_cuts = 0;
    options.newton.max_iterations = 8;
    options.newton.residual_tolerance = 1e-10;
    solver::StepperCallbacks callbacks;
    if (snapshots) callbacks.on_accepted = [&](const solver::StepperSnapshot& s) { snapshots->push_back(s); };
    return solver::solve_static(objective, options, {.characteristic_length = 1.0, .reference_force = 1.0},
                                callbacks, nullptr, resume, &stabilization);
  };
  std::vector<solver::StepperSnapshot> snapshots;
  const auto whole = run(nullptr, &snapshots);
  ASSERT_TRUE(whole.success) << whole.message;
  ASSERT_GE(whole.stabilized_steps, 2);
  int before = 0, after = 0;
  for (const solver::StepperSnapshot& snapshot : snapshots) {
    if (snapshot.t > 0.95) continue;
    (snapshot.scheme.stabilized ? after : before)++;
    const auto resumed = run(&snapshot, nullptr);
    ASSERT_TRUE(resumed.success) << resumed.message;
    EXPECT_EQ(resumed.steps, whole.steps);
    EXPECT_EQ(resumed.cuts, whole.cuts);
    EXPECT_EQ(resumed.stabilized_steps, whole.stabilized_steps);
    EXPECT_NEAR(resumed.dissipated, whole.dissipated, 1e-12 * whole.dissipated);
    EXPECT_LT((resumed.last_state.x - whole.last_state.x).cwiseAbs().maxCoeff(), 1e-12) << "from t = " << snapshot.t;
  }
  EXPECT_GE(before, 3);
  EXPECT_GE(after, 1);
}

// Nodal forces of 1e200 are finite, and so is the energy, but the residual's norm overflows:
// the residual and the force scale are infinite, and inf <= inf once passed the convergence
// test and the run reported "solved" after 0 iterations.
TEST(StaticSolver, OverflowingForcesAreNeverAnEquilibrium) {
  auto p = st::box_problem(2, 2, 2, Vector3(0, 0, 0), Vector3(1, 1, 1), st::mooney_rivlin(), 1e-100);
  p.gravity = Vector3(0, 0, -1e300);
  p.prescribed.push_back({"bottom", st::nodes_on_plane(p.mesh, 2, 0.0), {}});
  SolverRig run(std::move(p));
  solver::StaticSolverOptions options;
  options.stepping.increments = 1;
  const auto result = solver::solve_static(*run.objective, options, {.characteristic_length = 1.7, .reference_force = 1.0});
  EXPECT_FALSE(result.success);
  EXPECT_NE(result.message.find("not finite"), std::string::npos) << result.message;
}

// A full turn in one increment: the top of a column turned 360 degrees about its axis. Taken as
// one step, the turned top coincides with the rest pose and the column stays straight (torque
// ~0); the stepper must split it so the column is twisted, half a turn at mid-height.
TEST(StaticSolver, AFullTurnInOneIncrementIsTakenInStepsOfAtMostThirtyDegrees) {
  const double height = 12;
  auto p = st::box_problem(2, 2, 12, Vector3(0, 0, 0), Vector3(1, 1, height), st::mooney_rivlin(1.0, 0.3, 2.0));
  p.prescribed.push_back({"bottom", st::nodes_on_plane(p.mesh, 2, 0.0), {}});
  fem::RigidMotion turn;
  turn.axis = Vector3::UnitZ();
  turn.axis_point = Vector3(0.5, 0.5, 0);
  turn.angle = 2 * M_PI;
  p.prescribed.push_back({"top", st::nodes_on_plane(p.mesh, 2, height), turn});
  SolverRig run(std::move(p));
  solver::StaticSolverOptions options;
  options.stepping.increments = 1;
  const auto result =
      solver::solve_static(*run.objective, options, {.characteristic_length = height, .reference_force = 1.0});
  ASSERT_TRUE(result.success) << result.message;
  EXPECT_GE(result.steps, 12);
  // Mid-height corners have turned by about 180 degrees: (1, 1) is near (0, 0) and vice versa.
  const auto& x = result.last_state.x;
  const auto& X = run.problem.mesh.rest;
  int checked = 0;
  for (Index v = 0; v < X.rows(); ++v) {
    if (std::abs(X(v, 2) - height / 2) > 1e-9 || std::abs(X(v, 0) - 0.5) < 0.1) continue;
    const Vector3 from_axis_rest(X(v, 0) - 0.5, X(v, 1) - 0.5, 0);
    const Vector3 from_axis(x(v, 0) - 0.5, x(v, 1) - 0.5, 0);
    EXPECT_LT(from_axis.dot(from_axis_rest), -0.5 * from_axis_rest.squaredNorm()) << "node " << v;
    ++checked;
  }
  EXPECT_GT(checked, 0);
  // The twisted column carries a torque about z, far from zero.
  const auto g = run.objective->full_gradient(result.last_state);
  Vector3 moment = Vector3::Zero();
  for (Index v : st::nodes_on_plane(run.problem.mesh, 2, height))
    moment += (x.row(v) - Eigen::RowVector3d(0.5, 0.5, height)).transpose().cross(-g.row(v).transpose());
  EXPECT_GT(std::abs(moment.z()), 0.01);
}
