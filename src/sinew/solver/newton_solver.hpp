#pragma once
/// @file newton_solver.hpp
/// Damped Newton on the total potential at a fixed load parameter (dissertation Fig. 12,
/// loop 2 and 3): direction from K dq = -g (with optional quasi-viscosity), then a line
/// search that halves the step until the state is legal and the energy (or, as the seed
/// did, the residual norm) decreases.

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sinew/solver/linear_solver.hpp"
#include "sinew/solver/objective.hpp"

namespace sinew::solver {

/// One Newton iteration, for logs.
struct IterationRecord {
  int iteration = 0;              ///< 0 = the starting state (no step taken yet)
  double residual = 0;            ///< |g_q| (force unit)
  double force_scale = 0;         ///< the scale the residual is compared against
  double energy = 0;              ///< Pi
  double step_length = 0;         ///< line-search alpha of the step that led here
  int line_search_steps = 0;      ///< halvings of that step
  int linear_iterations = 0;      ///< of the linear solve that led here
  double increment = 0;           ///< largest node displacement of that step (length)
  double regularization = 0;      ///< diagonal shift added to K, relative to its diagonal
  /// |g_q| without the transient terms (inertia, viscosity of time integration): the force
  /// imbalance of the static problem at this iterate. Equals `residual` in static solves.
  double equilibrium_residual = 0;
};

/// Wall-clock seconds per phase, accumulated. The phases do not overlap: collision detection
/// (the terms' update and begin_step: the contact's broad and narrow phase) is taken out of
/// the phase during which it ran, and solve_static / solve_dynamic set `collision` to the
/// objective's collision time over the solve.
struct PhaseTimes {
  double forces_and_stiffness = 0;  ///< gradients, Hessians, reduction to q-space
  double collision = 0;             ///< broad and narrow phase (BVH refit, queries, clipping)
  double linear_solve = 0;          ///< analyze, factorize, solve
  double line_search = 0;           ///< energy evaluations of trial states
  double other = 0;
  double total() const { return forces_and_stiffness + collision + linear_solve + line_search + other; }
};

/// What the linear solves cost, counted over a solver's life.
struct LinearCounts {
  int factorizations = 0;     ///< numeric factorizations, shifted retries included
  int linear_iterations = 0;  ///< iterations of iterative or lagged solves
  /// Lagged (inexact) Newton steps undone because they multiplied the residual by more than
  /// NewtonOptions::max_lagged_residual_growth, and solved again exactly.
  int undone_lagged_steps = 0;
};

/// Adds the wall time of its scope to `sink`, except the time `objective` spent in collision
/// detection meanwhile (Objective::collision_seconds, counted as PhaseTimes::collision).
class PhaseTimer {
 public:
  PhaseTimer(double& sink, const Objective& objective);
  ~PhaseTimer();
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  double& sink_;
  const Objective& objective_;
  double collision_start_;
  std::chrono::steady_clock::time_point start_;
};

struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0;
  double force_scale = 0;
  double energy = 0;
  std::string failure;  ///< why it stopped without converging
};

/// What Newton needs to know of the model besides its objective.
struct NewtonSetup {
  double characteristic_length = 1;  ///< for the increment criterion (length)
  /// Force of order (stiffest initial modulus, shear or bulk) x (characteristic length)^2.
  /// Residuals below 1e-13 of it are round-off and count as converged whatever the relative
  /// criterion says (a state with no load at all has nothing to be relative to). 0 disables
  /// the floor.
  double reference_force = 0;
  VectorX node_viscosity;  ///< quasi-viscosity per node (force / length), #V, or empty
  /// Terms of the objective that belong to time integration (inertia, viscosity): left out of
  /// IterationRecord::equilibrium_residual. Not owned.
  std::vector<const Energy*> transient_terms;
  /// On several MPI ranks: the rank owning each node (#V, parallel::node_owners), whose rows of K
  /// that rank holds in a linear solve shared among the ranks (PETSc's); empty on one rank.
  std::vector<int> node_owner;
};

/// Damped Newton on an Objective. Owns the q-space tangent K, the linear solver with its
/// symbolic analysis and last factorization, and the time per phase, all kept between solves
/// (the pattern and the analysis are reused while the contact pairs do not change it).
class NewtonSolver {
 public:
  using IterationCallback = std::function<void(const IterationRecord&)>;

  /// `objective` must outlive the solver.
  NewtonSolver(Objective& objective, const LinearSolverOptions& linear, NewtonSetup setup);

  /// Runs Newton from `state` (updated in place; on failure it holds the last iterate) at the
  /// objective's current load parameter. `on_iteration` sees the starting state (iteration 0)
  /// and every accepted iterate.
  NewtonResult solve(fem::State& state, const NewtonOptions& options, const IterationCallback& on_iteration = {});

  /// Makes sure a factorization exists: when no Newton step has factorized yet, assembles and
  /// factorizes the tangent at `state` (`full_gradient`: dPi/dx there, #V x 3). Otherwise the
  /// last factorization (of the last Newton iteration's K, perhaps shifted) stays. Returns
  /// whether a usable factorization exists.
  bool ensure_factorization(const fem::State& state, const NodalVectors& full_gradient);
  /// Solves K x = rhs (#q) with the last factorization; false when that fails.
  bool solve_with_last_factorization(const VectorX& rhs, VectorX& x);

  Objective& objective() { return objective_; }
  const NewtonSetup& setup() const { return setup_; }
  /// Accumulated over the solver's life; `collision` is left to the caller (see PhaseTimes).
  PhaseTimes& times() { return times_; }
  /// Accumulated over the solver's life.
  LinearCounts counts() const;

 private:
  /// A point of the line search: the state, its energy and (once computed) its gradient.
  struct TrialPoint {
    fem::State state;
    double energy = 0;
    NodalVectors full_g;  ///< #V x 3; 0 rows until computed
    VectorX g;            ///< #q
    double scale = 0;     ///< force scale at `state`
  };
  /// After the full step `point` = state + dq was accepted: while the energy's slope along dq at
  /// the point is below kExtrapolationSlopeRatio x `slope` (the slope at `state`, < 0), tries the
  /// doubled step and keeps it when it is legal and lowers the energy, up to `max_growth` x dq.
  /// Returns the step length taken (1 when nothing better was found); `point` holds its
  /// gradient on return.
  double extrapolate(const fem::State& state, const VectorX& dq, double slope, double max_growth, TrialPoint& point);
  /// Before a factorization: gives the linear solver the ranks that hold the unknowns' rows (on
  /// several MPI ranks, once per DofMap) and the rigid-body modes at `state` when its
  /// preconditioner uses them.
  void prepare_linear_solver(const fem::State& state);

  Objective& objective_;
  std::unique_ptr<LinearSolver> linear_;
  SparseMatrix K_;
  bool factorized_ = false;  ///< the linear solver holds a factorization of some K
  Index owners_passed_for_ = -1;  ///< the unknowns' count the linear solver's row owners were set for
  NewtonSetup setup_;
  PhaseTimes times_;
  int linear_iterations_ = 0;
  int undone_lagged_steps_ = 0;
  /// The shift the last climb from an unshifted failure reached (0: none yet), kept
  /// between solves: a tangent that turns indefinite again usually needs a shift of that scale,
  /// and climbing tenfold from the smallest shift costs up to ten failed factorizations.
  double last_shift_ = 0;
};

}  // namespace sinew::solver
