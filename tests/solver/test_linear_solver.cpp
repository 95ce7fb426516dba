/// @file test_linear_solver.cpp
/// The linear solvers behind Newton: each solves an SPD system, and keeps working after the
/// matrix it factorized is gone (Newton factorizes regularized temporaries; the tangent
/// predictor solves with the last factorization later). The second case was a use-after-free
/// that crashed the knee flexion with std::bad_alloc.

#include "sinew/solver/linear_solver.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <Eigen/CholmodSupport>
#include <SuiteSparse_config.h>

#include "sinew/core/error.hpp"
#include "sinew/solver/serial_openmp.hpp"

namespace sinew::solver {
namespace {

/// A 1D Laplacian plus a diagonal shift: SPD, n x n.
fem::SparseMatrix laplacian(int n, double shift) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 2.0 + shift);
    if (i > 0) entries.emplace_back(i, i - 1, -1.0);
    if (i + 1 < n) entries.emplace_back(i, i + 1, -1.0);
  }
  fem::SparseMatrix K(n, n);
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

class LinearSolvers : public ::testing::TestWithParam<LinearSolverOptions::Kind> {};

TEST_P(LinearSolvers, SolveWorksAfterTheFactorizedMatrixIsDestroyed) {
  LinearSolverOptions options;
  options.kind = GetParam();
  options.tolerance = 1e-12;
  options.max_iterations = 1000;
  auto solver = make_linear_solver(options);
  const int n = 200;
  const fem::SparseMatrix pattern = laplacian(n, 0.5);
  solver->analyze(pattern);
  {
    const fem::SparseMatrix temporary = laplacian(n, 0.5);  // as Newton's regularized copy
    ASSERT_TRUE(solver->factorize(temporary));
  }
  // Overwrite the freed memory's likely neighbourhood with other matrices.
  std::vector<fem::SparseMatrix> clutter;
  for (int k = 0; k < 8; ++k) clutter.push_back(laplacian(n + k, 10.0 * k));
  const VectorX expected = VectorX::LinSpaced(n, -1.0, 1.0);
  const VectorX b = pattern * expected;
  VectorX x;
  const LinearSolveStats stats = solver->solve(b, x);
  EXPECT_TRUE(stats.success) << solver->name();
  EXPECT_LT(stats.relative_residual, 1e-8) << solver->name();
  EXPECT_LT((x - expected).norm(), 1e-6 * expected.norm()) << solver->name();
}

INSTANTIATE_TEST_SUITE_P(AllKinds, LinearSolvers,
                         ::testing::Values(LinearSolverOptions::Kind::Cholmod, LinearSolverOptions::Kind::Gmres,
                                           LinearSolverOptions::Kind::ConjugateGradient,
                                           LinearSolverOptions::Kind::PetscGamg, LinearSolverOptions::Kind::PetscMumps));

// CHOLMOD factorizes K's lower triangle: K is handed over upper-stored with its lower triangle
// mirrored (one transpose fewer inside CHOLMOD), and the answer is the lower-stored CHOLMOD's to
// the last bit, however much the upper triangle differs.
TEST(CholmodSolver, SolvesWithTheLowerTriangleToTheBitsOfALowerStoredFactorization) {
  const int n = 400;
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 8.0 + 0.01 * i);
    for (const int offset : {1, 7, 53}) {
      if (i + offset >= n) continue;
      const double lower = -1.0 - 1e-3 * ((i * offset) % 17);
      entries.emplace_back(i + offset, i, lower);
      entries.emplace_back(i, i + offset, lower * (1 + 1e-3));  // the upper twin differs
    }
  }
  fem::SparseMatrix K(n, n);
  K.setFromTriplets(entries.begin(), entries.end());
  const VectorX b = VectorX::LinSpaced(n, -1.0, 3.0);

  Eigen::CholmodSupernodalLLT<fem::SparseMatrix, Eigen::Lower> lower_stored;
  VectorX expected;
  {
    const SerialOpenMpScope one_thread;  // as the solver runs CHOLMOD
    lower_stored.compute(K);
    ASSERT_EQ(lower_stored.info(), Eigen::Success);
    expected = lower_stored.solve(b);
  }
  auto solver = make_linear_solver({});
  solver->analyze(K);
  ASSERT_TRUE(solver->factorize(K));
  VectorX x;
  ASSERT_TRUE(solver->solve(b, x).success);
  for (int i = 0; i < n; ++i) ASSERT_EQ(x[i], expected[i]) << "entry " << i;
  // The upper triangle's values would have given another answer.
  const fem::SparseMatrix upper_symmetric = fem::SparseMatrix(K.triangularView<Eigen::Upper>()).selfadjointView<Eigen::Upper>();
  Eigen::CholmodSupernodalLLT<fem::SparseMatrix, Eigen::Upper> upper_stored(upper_symmetric);
  EXPECT_GT((upper_stored.solve(b) - expected).norm(), 1e-6 * expected.norm());
  // A second matrix of the same pattern reuses the map: again the lower-stored answer.
  const fem::SparseMatrix doubled = 2.0 * K;
  ASSERT_TRUE(solver->factorize(doubled));
  ASSERT_TRUE(solver->solve(b, x).success);
  EXPECT_LT((x - 0.5 * expected).norm(), 1e-13 * expected.norm());
}

// A factorization that fails stops at the failing supernode without leaving a partial factor:
// the next matrix of the same pattern is factorized and solved as if the failure had not been.
TEST(CholmodSolver, AFailedFactorizationLeavesNothingBehindForTheNext) {
  const int n = 500;
  const fem::SparseMatrix spd = laplacian(n, 0.25);
  const fem::SparseMatrix indefinite = laplacian(n, -0.5);  // eigenvalues down to -0.5
  const VectorX expected = VectorX::LinSpaced(n, 1.0, -2.0);
  auto fresh = make_linear_solver({});
  fresh->analyze(spd);
  ASSERT_TRUE(fresh->factorize(spd));
  VectorX reference;
  ASSERT_TRUE(fresh->solve(spd * expected, reference).success);
  auto solver = make_linear_solver({});
  solver->analyze(spd);
  for (int round = 0; round < 3; ++round) {
    EXPECT_FALSE(solver->factorize(indefinite));
    ASSERT_TRUE(solver->factorize(spd));
    VectorX x;
    ASSERT_TRUE(solver->solve(spd * expected, x).success);
    for (int i = 0; i < n; ++i) ASSERT_EQ(x[i], reference[i]) << "round " << round << ", entry " << i;
  }
}

// CHOLMOD's allocations go through SuiteSparse_config; one that fails during the numeric
// factorization must be reported as memory, not as an indefinite matrix (which Newton would
// answer by shifting and halving the step until the run is killed).
void* failing_malloc(std::size_t) { return nullptr; }
void* failing_calloc(std::size_t, std::size_t) { return nullptr; }
void* failing_realloc(void*, std::size_t) { return nullptr; }

TEST(CholmodSolver, OutOfMemoryIsItsOwnError) {
  auto solver = make_linear_solver({});
  const fem::SparseMatrix K = laplacian(300, 0.5);
  solver->analyze(K);
  const SuiteSparse_config_struct saved = SuiteSparse_config;
  SuiteSparse_config.malloc_func = failing_malloc;
  SuiteSparse_config.calloc_func = failing_calloc;
  SuiteSparse_config.realloc_func = failing_realloc;
  bool thrown = false;
  try {
    solver->factorize(K);
  } catch (const OutOfMemoryError& e) {
    thrown = true;
    EXPECT_NE(std::string(e.what()).find("out of memory"), std::string::npos) << e.what();
  } catch (...) {
    SuiteSparse_config = saved;
    throw;
  }
  SuiteSparse_config = saved;
  EXPECT_TRUE(thrown);
  // Memory back: the same solver factorizes and solves.
  ASSERT_TRUE(solver->factorize(K));
  VectorX x;
  EXPECT_TRUE(solver->solve(VectorX::Ones(300), x).success);
}

// Lagged factorizations: a nearby matrix is solved by CG preconditioned with the factor of the
// first, without a factorization of its own; a matrix too far from it for the iteration budget is
// factorized and solved directly; an indefinite one is reported as not solved (Newton shifts).
TEST(CholmodSolver, LaggedFactorizationPreconditionsTheNextMatrices) {
  LinearSolverOptions options;
  options.lagged_iterations = 10;
  options.lagged_tolerance = 1e-10;
  auto solver = make_linear_solver(options);
  const int n = 300;
  const VectorX expected = VectorX::LinSpaced(n, -1.0, 2.0);
  const fem::SparseMatrix first = laplacian(n, 0.5);
  solver->analyze(first);
  ASSERT_TRUE(solver->factorize(first));
  EXPECT_EQ(solver->factorizations(), 1);
  VectorX x;
  LinearSolveStats stats = solver->solve(first * expected, x);
  ASSERT_TRUE(stats.success);
  EXPECT_LE(stats.iterations, 2) << "the exact factor preconditions its own matrix perfectly";

  const fem::SparseMatrix near = laplacian(n, 0.52);  // 1 % off on the diagonal
  ASSERT_TRUE(solver->factorize(near));
  stats = solver->solve(near * expected, x);
  ASSERT_TRUE(stats.success);
  EXPECT_EQ(solver->factorizations(), 1) << "no factorization: CG with the lagged factor converged";
  EXPECT_GT(stats.iterations, 1);
  EXPECT_LE(stats.iterations, 10);
  EXPECT_LT((near * x - near * expected).norm(), 1e-10 * (near * expected).norm());
  EXPECT_LT((x - expected).norm(), 1e-8 * expected.norm());

  const fem::SparseMatrix far = laplacian(n, 50.0);  // CG needs more than 10 iterations
  ASSERT_TRUE(solver->factorize(far));
  stats = solver->solve(far * expected, x);
  ASSERT_TRUE(stats.success);
  EXPECT_EQ(solver->factorizations(), 2) << "factorized after the lagged CG ran out of iterations";
  EXPECT_EQ(stats.iterations, 10);
  EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());

  const fem::SparseMatrix indefinite = laplacian(n, -1.5);
  ASSERT_TRUE(solver->factorize(indefinite));  // deferred: the answer comes with the solve
  stats = solver->solve(indefinite * expected, x);
  EXPECT_FALSE(stats.success) << "negative curvature, then a failed factorization";
  EXPECT_EQ(solver->factorizations(), 3);
  // No good factor is left: the next matrix is factorized at once.
  EXPECT_TRUE(solver->factorize(first));
  EXPECT_EQ(solver->factorizations(), 4);
}

// A new sparsity pattern is analyzed only when a factorization is needed: until then the old
// factor keeps preconditioning (its size is the same).
TEST(CholmodSolver, LaggedFactorizationSurvivesANewPattern) {
  LinearSolverOptions options;
  options.lagged_iterations = 20;
  options.lagged_tolerance = 1e-10;
  auto solver = make_linear_solver(options);
  const int n = 100;
  const fem::SparseMatrix tridiagonal = laplacian(n, 0.5);
  solver->analyze(tridiagonal);
  ASSERT_TRUE(solver->factorize(tridiagonal));
  fem::SparseMatrix wider = tridiagonal;
  wider.coeffRef(0, n - 1) = -0.01;  // a new entry: a contact pair between the ends
  wider.coeffRef(n - 1, 0) = -0.01;
  solver->analyze(wider);
  ASSERT_TRUE(solver->factorize(wider));
  const VectorX expected = VectorX::Ones(n);
  VectorX x;
  const LinearSolveStats stats = solver->solve(wider * expected, x);
  ASSERT_TRUE(stats.success);
  EXPECT_EQ(solver->factorizations(), 1);
  EXPECT_LT((x - expected).norm(), 1e-8 * expected.norm());
  // Forced past the budget, it analyzes the new pattern and factorizes.
  const fem::SparseMatrix far = wider * 40.0;
  ASSERT_TRUE(solver->factorize(far));
  EXPECT_TRUE(solver->solve(far * expected, x).success);
  EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());
}

}  // namespace
}  // namespace sinew::solver
