#include "sinew/solver/newton_direction.hpp"

#include <algorithm>
#include <limits>

namespace sinew::solver {

Direction newton_direction(const SparseMatrix& K, bool fresh_pattern, const VectorX& g, LinearSolver& linear,
                           const ShiftStart& start) {
  Direction d;
  const int factorizations_before = linear.factorizations();
  if (fresh_pattern) linear.analyze(K);
  const VectorX diag = K.diagonal().cwiseAbs().cwiseMax(1e-300);
  double shift = start.first >= kSmallestShift ? start.first : 0;
  SparseMatrix shifted;
  for (int attempt = 0; attempt < 12; ++attempt) {
    const SparseMatrix* M = &K;
    if (shift > 0) {
      shifted = K;
      for (int k = 0; k < shifted.outerSize(); ++k) shifted.coeffRef(k, k) += shift * diag[k];
      M = &shifted;
    }
    ++d.attempts;
    if (linear.factorize(*M)) {
      VectorX dq;
      const LinearSolveStats stats = linear.solve(-g, dq);
      d.linear_iterations += stats.iterations;
      if (stats.success && g.dot(dq) < 0) {
        d.dq = std::move(dq);
        d.regularization = shift;
        d.lagged = stats.lagged;
        d.factorizations = linear.factorizations() - factorizations_before;
        return d;
      }
    }
    shift = shift == 0 ? std::max(kSmallestShift, start.after_unshifted_failure) : shift * 10;
  }
  // Last resort: diagonally scaled steepest descent.
  d.dq = -g.cwiseQuotient(diag);
  d.regularization = std::numeric_limits<double>::infinity();
  d.factorizations = linear.factorizations() - factorizations_before;
  return d;
}

}  // namespace sinew::solver
