#pragma once
/// @file objective.hpp
/// The total potential Pi = sum of energy terms, seen through the DofMap: what Newton
/// minimizes. Owns the Hessian's node-block pattern and rebuilds it when it must.

#include <vector>

#include "sinew/fem/dof_map.hpp"
#include "sinew/fem/energy.hpp"

namespace sinew::solver {

class Objective {
 public:
  /// `terms` are not owned and must outlive the objective.
  Objective(fem::DofMap& dofs, std::vector<fem::Energy*> terms, Index num_nodes);

  void set_load_parameter(double lambda);
  /// Sum of the terms; +inf when any term or validity check says the state is illegal.
  double value(const fem::State& state) const;
  bool is_valid(const fem::State& state) const;
  /// Full-space gradient dPi/dx, #V x 3. When `force_scale` is given it receives the largest
  /// of the terms' own gradient norms: the magnitude of the forces that balance each other
  /// (internal forces, loads, reactions), against which residuals are judged.
  fem::NodalVectors full_gradient(const fem::State& state, double* force_scale = nullptr) const;
  /// Assembles the q-space Hessian into K (pattern kept between calls unless it changed;
  /// returns true when the pattern is new, so the linear solver must re-analyze).
  bool hessian(const fem::State& state, const fem::NodalVectors& full_gradient, const VectorX& node_viscosity,
               fem::SparseMatrix& K);
  /// Full-space Hessian of the last hessian() call (for tangent predictors and tests).
  const fem::BlockSparseMatrix& full_hessian() const { return H_; }
  const fem::DofMap& dofs() const { return dofs_; }
  const std::vector<fem::Energy*>& terms() const { return terms_; }

 private:
  void rebuild_pattern();
  fem::DofMap& dofs_;
  std::vector<fem::Energy*> terms_;
  Index num_nodes_;
  fem::BlockSparseMatrix H_;
  bool pattern_ready_ = false;
};

}  // namespace sinew::solver
