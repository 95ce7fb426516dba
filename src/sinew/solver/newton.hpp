#pragma once
/// @file newton.hpp
/// Damped Newton on the total potential at a fixed load parameter (dissertation Fig. 12,
/// loop 2 and 3): direction from K dq = -g (with optional quasi-viscosity), then a line
/// search that halves the step until the state is legal and the energy (or, as the seed
/// did, the residual norm) decreases.

#include <chrono>
#include <functional>
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

struct NewtonContext {
  double characteristic_length = 1;  ///< for the increment criterion (length)
  /// Force of order (stiffest initial modulus, shear or bulk) x (characteristic length)^2.
  /// Residuals below 1e-13 of it are round-off and count as converged whatever the relative
  /// criterion says (a state with no load at all has nothing to be relative to). 0 disables
  /// the floor.
  double reference_force = 0;
  VectorX node_viscosity;            ///< quasi-viscosity per node (force / length), or empty
  /// Terms of the objective that belong to time integration (inertia, viscosity): left out of
  /// IterationRecord::equilibrium_residual. Not owned.
  std::vector<const Energy*> transient_terms;
  std::function<void(const IterationRecord&)> on_iteration;
};

/// Runs Newton from `state` (updated in place; on failure it holds the last iterate).
/// `K` and `linear` keep their pattern and factorization between calls.
NewtonResult newton_solve(Objective& objective, fem::State& state, const NewtonOptions& options,
                          LinearSolver& linear, fem::SparseMatrix& K, const NewtonContext& context,
                          PhaseTimes& times);

}  // namespace sinew::solver
