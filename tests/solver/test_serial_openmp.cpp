/// @file test_serial_openmp.cpp
/// CHOLMOD's OpenMP regions run on the calling thread (serial_openmp.hpp): a factorization
/// through sinew's solver starts no OpenMP worker thread, while the same factorization through
/// CHOLMOD directly does (this is what the scope is for; where a CHOLMOD opens no OpenMP team at
/// all, the test says so and skips).

#include "sinew/solver/serial_openmp.hpp"

#include <gtest/gtest.h>

#include <Eigen/CholmodSupport>

#include <filesystem>
#include <vector>

#include "sinew/solver/linear_solver.hpp"

namespace sinew::solver {
namespace {

/// Threads of this process (Linux: the entries of /proc/self/task).
int process_threads() {
  int count = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator("/proc/self/task")) ++count;
  return count;
}

/// The 7-point Laplacian on an n x n x n grid plus a small shift: SPD, n^3 x n^3, with the large
/// supernodes whose updates CHOLMOD scatters in OpenMP regions.
fem::SparseMatrix grid_laplacian(int n) {
  std::vector<Eigen::Triplet<double>> entries;
  const auto id = [n](int i, int j, int k) { return (i * n + j) * n + k; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const int a = id(i, j, k);
        entries.emplace_back(a, a, 6.01);
        if (i > 0) entries.emplace_back(a, id(i - 1, j, k), -1.0);
        if (i + 1 < n) entries.emplace_back(a, id(i + 1, j, k), -1.0);
        if (j > 0) entries.emplace_back(a, id(i, j - 1, k), -1.0);
        if (j + 1 < n) entries.emplace_back(a, id(i, j + 1, k), -1.0);
        if (k > 0) entries.emplace_back(a, id(i, j, k - 1), -1.0);
        if (k + 1 < n) entries.emplace_back(a, id(i, j, k + 1), -1.0);
      }
  fem::SparseMatrix K(n * n * n, n * n * n);
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

TEST(SerialOpenMpScope, SetsNoActiveLevelsAndRestoresThem) {
  const int before = omp_get_max_active_levels();
  {
    const SerialOpenMpScope outer;
    EXPECT_EQ(omp_get_max_active_levels(), 0);
    {
      const SerialOpenMpScope inner;
      EXPECT_EQ(omp_get_max_active_levels(), 0);
    }
    EXPECT_EQ(omp_get_max_active_levels(), 0);
  }
  EXPECT_EQ(omp_get_max_active_levels(), before);
}

TEST(SerialOpenMpScope, CholmodFactorizationStartsNoOpenMpThreads) {
  const fem::SparseMatrix K = grid_laplacian(22);
  const VectorX b = VectorX::Ones(K.rows());

  // sinew's CHOLMOD solver first: the OpenMP runtime has started no team in this process yet.
  const int threads_before = process_threads();
  auto solver = make_linear_solver({});
  solver->analyze(K);
  ASSERT_TRUE(solver->factorize(K));
  VectorX x;
  ASSERT_TRUE(solver->solve(b, x).success);
  EXPECT_LT((K * x - b).norm(), 1e-10 * b.norm());
  EXPECT_EQ(process_threads(), threads_before) << "a factorization through sinew's solver started threads";

  // The control: CHOLMOD called directly opens its team, whose threads then stay parked.
  Eigen::CholmodSupernodalLLT<fem::SparseMatrix, Eigen::Lower> direct;
  direct.compute(K);
  ASSERT_EQ(direct.info(), Eigen::Success);
  if (process_threads() == threads_before)
    GTEST_SKIP() << "this CHOLMOD opened no OpenMP team when called directly either: nothing to keep off";
}

}  // namespace
}  // namespace sinew::solver
