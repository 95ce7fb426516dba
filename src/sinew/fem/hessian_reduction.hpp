#pragma once
/// @file hessian_reduction.hpp
/// Full-space Hessians (#V x #V node blocks of 3 x 3) to the q-space tangent K of a DofMap,
/// K = Jᵀ H J + the second-order term of the rotation map of free rigid bodies + the
/// quasi-viscosity diagonal, with K's sparsity pattern and the destination of every block entry
/// computed once per H pattern.

#include <cstdint>
#include <vector>

#include "sinew/core/block_sparse_matrix.hpp"
#include "sinew/fem/dof_map.hpp"

namespace sinew::fem {

class HessianReduction {
 public:
  /// `dofs` must outlive the reduction.
  explicit HessianReduction(const DofMap& dofs);

  /// Builds the q-space pattern for H's pattern (call when H.pattern_version() changes).
  void bind(const BlockSparseMatrix& H);
  /// Whether bind() saw H's current pattern.
  bool is_bound_to(const BlockSparseMatrix& H) const { return bound_version_ == H.pattern_version(); }
  /// K (#q x #q) from H at `state` (g: dPi/dx, #V x 3, for the rotation term; node_viscosity:
  /// per node, #V, or empty). K takes the bound pattern (a fresh K, or one of another pattern)
  /// or keeps it (values overwritten).
  void reduce(const State& state, const BlockSparseMatrix& H, const NodalVectors& g, const VectorX& node_viscosity,
              SparseMatrix& K) const;

 private:
  const DofMap& dofs_;
  std::uint64_t bound_version_ = 0;
  /// K's pattern (compressed columns) without values: a zero matrix beside K would be another
  /// 8 bytes per nonzero (docs/mpi.md).
  std::vector<int> pattern_outer_, pattern_inner_;
  std::vector<Index> block_target_offset_;  ///< per H block, into targets_
  std::vector<Index> targets_;              ///< value indices into K, row-major per block
  std::vector<Index> diagonal_target_;      ///< per q index, value index of (i, i)
};

}  // namespace sinew::fem
