#include "sinew/solver/triangle_mirror.hpp"

#include <fmt/format.h>

#include "sinew/core/error.hpp"

namespace sinew::solver {
namespace {

Error no_twin(int row, int column) {
  return Error(fmt::format("triangle mirror: entry ({}, {}) has no twin ({}, {}): the pattern is not symmetric", row,
                           column, column, row));
}

}  // namespace

TriangleMirror triangle_mirror(const SparseMatrix& pattern) {
  if (pattern.rows() != pattern.cols() || !pattern.isCompressed())
    throw Error(fmt::format("triangle mirror: the matrix must be square and compressed ({} x {})", pattern.rows(),
                            pattern.cols()));
  const int n = static_cast<int>(pattern.rows());
  const int* start = pattern.outerIndexPtr();
  const int* row = pattern.innerIndexPtr();
  TriangleMirror mirror;
  mirror.rows = n;
  mirror.stored = static_cast<int>(pattern.nonZeros());
  // Column c's entries above the diagonal are rows r < c in increasing order; their twins (c, r)
  // are met in that same order when the columns r are walked in increasing order. So a cursor
  // per column c finds each twin without a search.
  std::vector<int> cursor(start, start + n);
  // A symmetric pattern has at most (nonzeros - diagonal) / 2 entries above its diagonal.
  mirror.upper.reserve(static_cast<std::size_t>(mirror.stored) / 2);
  mirror.lower.reserve(static_cast<std::size_t>(mirror.stored) / 2);
  for (int r = 0; r < n; ++r) {
    for (int k = start[r]; k < start[r + 1]; ++k) {
      const int c = row[k];
      if (c <= r) continue;  // (c, r) with c > r lies below the diagonal; its twin is (r, c)
      const int twin = cursor[static_cast<std::size_t>(c)]++;
      if (twin < start[c + 1] && row[twin] < r) throw no_twin(row[twin], c);  // (row[twin], c) was skipped
      if (twin >= start[c + 1] || row[twin] != r) throw no_twin(c, r);
      mirror.upper.push_back(twin);
      mirror.lower.push_back(k);
    }
  }
  // Every entry above the diagonal must have been a twin.
  for (int c = 0; c < n; ++c)
    if (const int next = cursor[static_cast<std::size_t>(c)]; next < start[c + 1] && row[next] < c)
      throw no_twin(row[next], c);
  return mirror;
}

bool fits(const TriangleMirror& mirror, const SparseMatrix& matrix) {
  return matrix.isCompressed() && matrix.rows() == mirror.rows && matrix.cols() == mirror.rows &&
         matrix.nonZeros() == mirror.stored;
}

void mirror_lower_to_upper(const TriangleMirror& mirror, SparseMatrix& matrix) {
  double* values = matrix.valuePtr();
  for (std::size_t k = 0; k < mirror.upper.size(); ++k) values[mirror.upper[k]] = values[mirror.lower[k]];
}

}  // namespace sinew::solver
