#pragma once
/// @file linear_solver.hpp
/// Linear solvers for the Newton systems K dq = -g (K symmetric, usually positive definite):
/// CHOLMOD's supernodal Cholesky (default; optionally lagged: the last factorization
/// preconditions CG on the next matrices until CG needs too many iterations, docs/solver.md),
/// GMRES with diagonal preconditioning stopped at a loose relative residual (the seed's choice),
/// and diagonally preconditioned CG.

#include <functional>
#include <memory>
#include <vector>

#include "sinew/fem/dof_map.hpp"
#include "sinew/solver/solver_config.hpp"

namespace sinew::solver {

using fem::SparseMatrix;

struct LinearSolveStats {
  bool success = false;
  int iterations = 0;             ///< 0 for direct solvers
  double relative_residual = 0;   ///< |K x - b| / |b|
  /// Solved by CG preconditioned with an earlier matrix's factorization (lagged CHOLMOD): an
  /// inexact solution, where require_relative_residual(0) would give an exact one.
  bool lagged = false;
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  /// Symbolic work for K's sparsity pattern (call again when the pattern changes).
  virtual void analyze(const SparseMatrix& K) = 0;
  /// Numeric setup for K's values. Returns false when K cannot be factorized (Cholesky of an
  /// indefinite matrix); the caller then regularizes.
  virtual bool factorize(const SparseMatrix& K) = 0;
  /// Solves K x = b with the last factorized K.
  virtual LinearSolveStats solve(const VectorX& b, VectorX& x) = 0;
  virtual const char* name() const = 0;
  /// Numeric factorizations done so far (an iterative solver's preconditioner setups).
  virtual int factorizations() const = 0;
  /// The next solves must reach |K x - b| <= eta |b| if they are inexact (lagged CHOLMOD: the
  /// smaller of eta and its lagged_tolerance; eta = 0: factorize, no lagged CG). Others ignore it.
  virtual void require_relative_residual(double /*eta*/) {}
  /// True when the solver's preconditioner uses the rigid-body modes (PETSc's GAMG): the caller
  /// then passes their source with set_rigid_body_motions before each factorize().
  virtual bool wants_rigid_body_modes() const { return false; }
  /// The rigid-body motions at the listed unknowns, #unknowns x 6, not orthonormal
  /// (fem::rigid_body_motions at the state of the next factorization).
  using RigidBodyMotions = std::function<MatrixX(const std::vector<Index>& unknowns)>;
  /// `motions`: called by the next factorize() for the unknowns of this process's rows (on several
  /// MPI ranks each takes its own: the modes are never whole on a rank, docs/mpi.md), and not
  /// kept after it; `block_size`: 3 when the unknowns come in aligned triples, else 1
  /// (fem::unknowns_block_size).
  virtual void set_rigid_body_motions(RigidBodyMotions /*motions*/, int /*block_size*/) {}
  /// On a solve shared among MPI ranks (PETSc's): `owner` (#unknowns, or empty) says which rank
  /// holds each unknown's row of K (solver/row_order.hpp); empty: contiguous ranges. Others
  /// ignore it.
  virtual void set_row_owners(std::vector<int> /*owner*/) {}
  /// True when factorize() takes this rank's part of K and adds the ranks' parts (PETSc's
  /// solvers on several MPI ranks): K's diagonal is then a sum over the ranks, and a shift of K is
  /// added by one rank (newton_direction). Else every rank passes the whole K.
  virtual bool adds_ranks_parts() const { return false; }
  /// Negative eigenvalues of the last matrix factorized when the solver knows its inertia (MUMPS's
  /// LDL^T), else -1.
  virtual long negative_eigenvalues() const { return -1; }
};

std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverOptions& options);

}  // namespace sinew::solver
