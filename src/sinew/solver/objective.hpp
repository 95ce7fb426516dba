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
  const BlockSparseMatrix& full_hessian() const { return H_; }
  const fem::DofMap& dofs() const { return dofs_; }
  /// Wall-clock seconds spent so far in the terms' update() and begin_step() (collision
  /// detection), accumulated over the objective's life.
  double collision_seconds() const { return collision_seconds_; }

 private:
  void rebuild_pattern();
  void update_terms(const fem::State& state);
  std::uint64_t pattern_revisions() const;
  std::uint64_t pattern_revision_ = 0;
  const fem::DofMap& dofs_;
  fem::HessianReduction reduction_;  ///< q-space pattern of H_
  std::vector<Energy*> terms_;
  Index num_nodes_;
  BlockSparseMatrix H_;
  bool pattern_ready_ = false;
  double collision_seconds_ = 0;
};

}  // namespace sinew::solver
