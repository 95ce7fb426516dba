#include "sinew/solver/newton_direction.hpp"

#include <algorithm>
#include <limits>

#include "sinew/parallel/ranks.hpp"

namespace sinew::solver {

Direction newton_direction(const SparseMatrix& K, bool fresh_pattern, const VectorX& g, LinearSolver& linear,
                           const ShiftStart& start) {
  Direction d;
  const int factorizations_before = linear.factorizations();
  if (fresh_pattern) linear.analyze(K);
  // With each rank's part of K (LinearSolver::adds_ranks_parts), the diagonal is their sum and the
  // shift is added by rank 0 alone.
  const bool parts = linear.adds_ranks_parts();
  VectorX whole_diagonal = K.diagonal();
  if (parts) parallel::sum(whole_diagonal.data(), static_cast<std::size_t>(whole_diagonal.size()));
  const VectorX diag = whole_diagonal.cwiseAbs().cwiseMax(1e-300);
  const bool adds_shift = !parts || parallel::is_root();
  double shift = start.first >= kSmallestShift ? start.first : 0;
  SparseMatrix shifted;
  for (int attempt = 0; attempt < 12; ++attempt) {
    const SparseMatrix* M = &K;
    if (shift > 0 && adds_shift) {
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
