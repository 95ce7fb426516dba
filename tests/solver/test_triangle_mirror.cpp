/// @file test_triangle_mirror.cpp
/// The lower triangle of a symmetric matrix copied onto its upper one through a map of twin
/// entries: the result is symmetric to the last bit, the lower triangle untouched, and a pattern
/// that is not symmetric is refused.

#include "sinew/solver/triangle_mirror.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <random>
#include <vector>

#include "sinew/core/error.hpp"

namespace sinew::solver {
namespace {

using ::testing::HasSubstr;

/// An n x n matrix with a random symmetric pattern (every diagonal entry, about `density` of the
/// rest) whose two triangles hold unrelated values.
SparseMatrix random_symmetric_pattern(int n, double density, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::bernoulli_distribution keep(density);
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < n; ++j) {
    entries.emplace_back(j, j, 4.0 + value(rng));
    for (int i = j + 1; i < n; ++i)
      if (keep(rng)) {
        entries.emplace_back(i, j, value(rng));
        entries.emplace_back(j, i, value(rng));
      }
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  return A;
}

TEST(TriangleMirror, MakesTheMatrixSymmetricToTheLastBitAndKeepsTheLowerTriangle) {
  const SparseMatrix original = random_symmetric_pattern(60, 0.2, 7);
  SparseMatrix A = original;
  const TriangleMirror mirror = triangle_mirror(A);
  ASSERT_TRUE(fits(mirror, A));
  EXPECT_EQ(mirror.upper.size(), static_cast<std::size_t>((A.nonZeros() - A.rows()) / 2));
  mirror_lower_to_upper(mirror, A);
  const SparseMatrix transposed = A.transpose();
  int compared = 0;
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
      EXPECT_EQ(it.value(), transposed.coeff(it.row(), it.col())) << it.row() << ", " << it.col();
      // Below the diagonal (and on it) the values are the original ones, above it their twins'.
      const double expected = it.row() >= it.col() ? original.coeff(it.row(), it.col()) : original.coeff(it.col(), it.row());
      EXPECT_EQ(it.value(), expected) << it.row() << ", " << it.col();
      ++compared;
    }
  EXPECT_EQ(compared, A.nonZeros());
  EXPECT_NE((original - SparseMatrix(original.transpose())).norm(), 0.0);  // the input was not symmetric
}

TEST(TriangleMirror, RefusesAPatternThatIsNotSymmetric) {
  for (const bool above : {true, false}) {
    SparseMatrix A = random_symmetric_pattern(12, 0.3, 3);
    // One extra entry without a twin, above or below the diagonal.
    const int i = above ? 2 : 9, j = above ? 9 : 2;
    A.coeffRef(i, j) = 0.0;
    A.coeffRef(j, i) = 0.0;
    A.prune([&](int r, int c, double) { return !(r == j && c == i); });
    A.makeCompressed();
    ASSERT_EQ(A.coeff(j, i), 0.0);
    try {
      triangle_mirror(A);
      ADD_FAILURE() << "no error for a lone entry (" << i << ", " << j << ")";
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), HasSubstr("not symmetric"));
      EXPECT_THAT(e.what(), HasSubstr(fmt::format("({}, {})", i, j)));
    }
  }
}

TEST(TriangleMirror, FitsOnlyAMatrixOfItsSizeAndEntries) {
  const SparseMatrix A = random_symmetric_pattern(20, 0.3, 11);
  const TriangleMirror mirror = triangle_mirror(A);
  EXPECT_TRUE(fits(mirror, A));
  EXPECT_FALSE(fits(mirror, random_symmetric_pattern(21, 0.3, 11)));
  // A pair of entries the pattern lacks: same size, two more entries.
  int row = -1;
  for (int r = 1; r < A.rows() && row < 0; ++r)
    if (A.coeff(r, 0) == 0.0) row = r;
  ASSERT_GE(row, 0);
  SparseMatrix grown = A;
  grown.coeffRef(row, 0) = 1.0;
  grown.coeffRef(0, row) = 1.0;
  grown.makeCompressed();
  EXPECT_FALSE(fits(mirror, grown));
}

}  // namespace
}  // namespace sinew::solver
