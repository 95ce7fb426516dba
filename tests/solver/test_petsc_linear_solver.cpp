/// @file test_petsc_linear_solver.cpp
/// PETSc's solvers on one process: MUMPS's LDL^T reports the inertia of what it factorizes and
/// refuses indefinite tangents as CHOLMOD does; CG + GAMG with the rigid-body modes solves an
/// elasticity tangent in few iterations and, through newton_direction, still yields a descent
/// direction when the tangent is indefinite.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "sinew/solver/linear_solver.hpp"
#include "sinew/solver/newton_direction.hpp"

namespace sinew::solver {
namespace {

/// 3D block version of a 1D Laplacian chain plus `shift` on the diagonal, n blocks of 3.
fem::SparseMatrix chain(int n, double shift) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) {
      const int r = 3 * i + c;
      entries.emplace_back(r, r, 2.0 + shift + 0.1 * c);
      if (i > 0) entries.emplace_back(r, r - 3, -1.0);
      if (i + 1 < n) entries.emplace_back(r, r + 3, -1.0);
    }
  fem::SparseMatrix K(3 * n, 3 * n);
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

long negative_count(const fem::SparseMatrix& K) {
  Eigen::SelfAdjointEigenSolver<MatrixX> eig{MatrixX(K)};
  return static_cast<long>((eig.eigenvalues().array() < 0).count());
}

TEST(PetscMumps, ReportsTheInertiaAndRefusesIndefiniteMatrices) {
  LinearSolverOptions options;
  options.kind = LinearSolverOptions::Kind::PetscMumps;
  auto solver = make_linear_solver(options);
  const fem::SparseMatrix spd = chain(40, 0.2);
  solver->analyze(spd);
  ASSERT_TRUE(solver->factorize(spd));
  EXPECT_EQ(solver->negative_eigenvalues(), 0);
  const fem::SparseMatrix indefinite = chain(40, -1.0);
  const long expected = negative_count(indefinite);
  ASSERT_GT(expected, 0);
  EXPECT_FALSE(solver->factorize(indefinite));
  EXPECT_EQ(solver->negative_eigenvalues(), expected);
  EXPECT_EQ(solver->factorizations(), 2);
}

TEST(PetscGamg, NewtonDirectionShiftsAnIndefiniteTangentToADescentDirection) {
  LinearSolverOptions options;
  options.kind = LinearSolverOptions::Kind::PetscGamg;
  options.tolerance = 1e-8;
  options.max_iterations = 300;
  auto solver = make_linear_solver(options);
  const fem::SparseMatrix K = chain(60, -1.0);  // indefinite
  ASSERT_GT(negative_count(K), 0);
  const VectorX g = VectorX::LinSpaced(K.rows(), -1.0, 2.0);
  const Direction d = newton_direction(K, true, g, *solver, ShiftStart{});
  EXPECT_GT(d.regularization, 0);
  EXPECT_TRUE(std::isfinite(d.regularization));
  EXPECT_LT(g.dot(d.dq), 0);
  EXPECT_GT(d.linear_iterations, 0);
}

TEST(PetscMumps, AgreesWithCholmodOnAnSpdSystem) {
  const fem::SparseMatrix K = chain(500, 0.05);
  const VectorX b = VectorX::LinSpaced(K.rows(), 1.0, -3.0);
  VectorX expected, x;
  auto cholmod = make_linear_solver({});
  cholmod->analyze(K);
  ASSERT_TRUE(cholmod->factorize(K));
  ASSERT_TRUE(cholmod->solve(b, expected).success);
  LinearSolverOptions options;
  options.kind = LinearSolverOptions::Kind::PetscMumps;
  auto mumps = make_linear_solver(options);
  mumps->analyze(K);
  ASSERT_TRUE(mumps->factorize(K));
  const LinearSolveStats stats = mumps->solve(b, x);
  EXPECT_TRUE(stats.success);
  EXPECT_LT((x - expected).norm(), 1e-10 * expected.norm());
}

}  // namespace
}  // namespace sinew::solver
