#pragma once
/// @file objective.hpp
/// The total potential Pi = sum of energy terms, seen through the DofMap: what Newton
/// minimizes. Owns the Hessian's node-block pattern and rebuilds it when it must.

#include <vector>

#include "sinew/fem/dof_map.hpp"
#include "sinew/fem/hessian_reduction.hpp"
#include "sinew/core/energy.hpp"

namespace sinew::solver {

class Objective {
 public:
  /// `terms` are not owned and must outlive the objective.
  Objective(const fem::DofMap& dofs, std::vector<Energy*> terms, Index num_nodes);

  void set_load_parameter(double lambda);
  /// Time stepping: the size (time) of the step about to be attempted (Energy::set_time_step).
  void set_time_step(double h);
  /// A load or time step starts at `state`: terms rebuild their acceleration structures.
  void begin_step(const fem::State& state);
  /// Sum of the terms; +inf when any term or validity check says the state is illegal.
  /// Non-const: terms refresh their x-dependent bookkeeping (Energy::update) first.
  double value(const fem::State& state);
  bool is_valid(const fem::State& state);
  /// Full-space gradient dPi/dx, #V x 3. When `force_scale` is given it receives the largest
  /// of the terms' own gradient norms: the magnitude of the forces that balance each other
  /// (internal forces, loads, reactions), against which residuals are judged.
  NodalVectors full_gradient(const fem::State& state, double* force_scale = nullptr);
  /// Assembles the q-space Hessian into K (pattern kept between calls unless it changed;
  /// returns true when the pattern is new, so the linear solver must re-analyze).
  bool hessian(const fem::State& state, const NodalVectors& full_gradient, const VectorX& node_viscosity,
               fem::SparseMatrix& K);
  /// Full-space Hessian of the last hessian() call (for tangent predictors and tests).
  /// On several ranks with set_hessian_summed(false), this rank's part of it.
  const BlockSparseMatrix& full_hessian() const { return H_; }
  const fem::DofMap& dofs() const { return dofs_; }
  /// Wall-clock seconds spent so far in the terms' update() and begin_step() (collision
  /// detection), accumulated over the objective's life.
  double collision_seconds() const { return collision_seconds_; }

  /// A run on several ranks (parallel::size() > 1, docs/mpi.md): `shared` has one flag per term
  /// (in the order given to the constructor). A shared term holds this rank's share of itself
  /// (the sum of the ranks' shares is the term: the elastic energy of the tets this rank owns,
  /// the contact pairs of those tets) and is evaluated on every rank; the other terms only on
  /// rank 0. Value, gradient and Hessian are summed over the ranks, and a state is valid when it
  /// is on every rank, so every rank gets the same results. A summed Hessian lies on the terms'
  /// whole patterns (Energy::whole_hessian_pattern, the same on every rank). Every rank must then
  /// call the objective's functions in the same order (they communicate).
  void share_terms(std::vector<bool> shared);
  /// On several ranks, whether hessian() sums the full-space Hessian over the ranks (true, the
  /// default: every rank gets the whole K). False leaves each rank's K its own part: its terms'
  /// Hessians reduced to the unknowns, with the reduction's quasi-viscosity and rigid-body terms
  /// from the gradient on rank 0 only, so that the ranks' parts add up to the whole K (for a
  /// linear solver that adds them, LinearSolver::adds_ranks_parts). Each rank's Hessian pattern
  /// then holds only the blocks of what it evaluates (its tets, the contact pairs' blocks, rank 0's
  /// terms) and the diagonal blocks of every node, so its memory falls with the ranks; K keeps
  /// every unknown's diagonal entry. No effect on one rank.
  void set_hessian_summed(bool summed);

 private:
  void rebuild_pattern();
  void update_terms(const fem::State& state);
  std::uint64_t pattern_revisions() const;
  /// The term i if this rank evaluates it (a shared term, or any on rank 0), else null.
  Energy* evaluated(std::size_t i) const;
  /// On several ranks, each rank holds and assembles only its part of the Hessian.
  bool assembles_parts() const { return !shared_.empty() && !hessian_summed_; }
  std::uint64_t pattern_revision_ = 0;
  const fem::DofMap& dofs_;
  fem::HessianReduction reduction_;  ///< q-space pattern of H_
  std::vector<Energy*> terms_;
  std::vector<bool> shared_;  ///< per term, whether it holds this rank's share (empty: one rank)
  Index num_nodes_;
  BlockSparseMatrix H_;
  bool pattern_ready_ = false;
  bool hessian_summed_ = true;
  double collision_seconds_ = 0;
};

}  // namespace sinew::solver
