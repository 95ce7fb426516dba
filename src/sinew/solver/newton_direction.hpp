#pragma once
/// @file newton_direction.hpp
/// The Newton direction dq from K dq = -g, regularized by a growing diagonal shift when K is
/// not positive definite (docs/solver.md, "Indefinite tangents").

#include "sinew/solver/linear_solver.hpp"

namespace sinew::solver {

struct Direction {
  VectorX dq;                  ///< #q, a descent direction (g · dq < 0)
  int linear_iterations = 0;   ///< of the iterative solver, summed over the attempts (0 for direct)
  int attempts = 0;            ///< matrices tried (K, then K + shift diag(K) for growing shifts)
  int factorizations = 0;      ///< numeric factorizations the attempts took (lagged CG may take none)
  bool lagged = false;         ///< dq came from a lagged (inexact) solve, see LinearSolveStats::lagged
  /// Relative diagonal shift that gave dq (0: none); +inf when every attempt failed and dq is
  /// diagonally scaled steepest descent.
  double regularization = 0;
};

/// Smallest relative diagonal shift tried; below it a shift is no shift.
inline constexpr double kSmallestShift = 1e-8;

/// Where the search for a working shift starts. Every failed attempt costs a factorization, so
/// callers start near the shifts that worked before (docs/solver.md, "Indefinite tangents").
struct ShiftStart {
  double first = 0;  ///< relative shift tried first (below kSmallestShift: the unshifted K)
  /// Shift tried after the unshifted K failed (raised to kSmallestShift): the scale of the
  /// shifts that worked lately, a tenth of the last one, instead of the smallest shift.
  double after_unshifted_failure = kSmallestShift;
};

/// Solves K dq = -g (K: #q x #q, g: #q). When K cannot be factorized or the result is not a
/// descent direction, retries with K + shift * |diag(K)|, the shift growing tenfold from
/// `start` (see ShiftStart), at most 12 attempts, then falls back to diagonally scaled steepest
/// descent. `fresh_pattern`: K's sparsity pattern is new and `linear` must analyze it first.
/// When `linear` adds the ranks' parts of K (LinearSolver::adds_ranks_parts), K is this rank's
/// part: collective, every rank must call it.
Direction newton_direction(const SparseMatrix& K, bool fresh_pattern, const VectorX& g, LinearSolver& linear,
                           const ShiftStart& start);

}  // namespace sinew::solver
