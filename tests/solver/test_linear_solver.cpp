/// @file test_linear_solver.cpp
/// The linear solvers behind Newton: each solves an SPD system, and keeps working after the
/// matrix it factorized is gone (Newton factorizes regularized temporaries; the tangent
/// predictor solves with the last factorization later). The second case was a use-after-free
/// that crashed the knee flexion with std::bad_alloc.

#include "sinew/solver/linear_solver.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <SuiteSparse_config.h>

#include "sinew/core/error.hpp"

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
                                           LinearSolverOptions::Kind::ConjugateGradient));

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

}  // namespace
}  // namespace sinew::solver
