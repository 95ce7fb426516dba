#pragma once
/// @file elastic_energy.hpp
/// Sum over deformable tets of V0 psi(F): the stored elastic energy (energy unit =
/// stress x volume). Tets whose material is null (rigid regions) contribute nothing.

#include <vector>

#include "sinew/core/energy.hpp"
#include "sinew/fem/tet_kinematics.hpp"
#include "sinew/material/material.hpp"

namespace sinew::fem {

struct ElasticEnergyOptions {
  /// Project each tet's dP/dF onto the positive semi-definite cone (a convex Newton model).
  bool project_hessians = false;
  /// On several MPI ranks, the tets this rank's share evaluates (#T flags, docs/mpi.md); empty:
  /// every tet. Only their laws and rest shapes are kept; whole_hessian_pattern() still lists
  /// the blocks of every deformable tet.
  std::vector<bool> evaluated_tets;
};

class ElasticEnergy final : public Energy {
 public:
  /// `tet_material`: one law per tet (#T), nullptr = rigid/no elastic energy. The deformable
  /// tets it evaluates are those options.evaluated_tets flags (all without flags).
  ElasticEnergy(const Positions& rest, const Tets& tets, std::vector<material::MaterialPtr> tet_material,
                ElasticEnergyOptions options = {});

  std::string_view name() const override { return "elastic"; }
  double value(const Positions& x) const override;
  void add_gradient(const Positions& x, NodalVectors& grad) const override;
  void add_hessian(const Positions& x, BlockSparseMatrix& H) const override;
  /// The blocks of the tets it evaluates.
  void hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const override;
  /// The blocks of every deformable tet, also those of other ranks' shares.
  void whole_hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const override;
  bool is_valid(const Positions& x) const override;

  /// Caches, for every deformable tet, the block indices of its 16 node pairs in H.
  /// Must be called after H's pattern is set and before add_hessian(). When H's pattern grew
  /// from the one bound last, the indices move by H.moved_block_index() (no search).
  void bind_pattern(const BlockSparseMatrix& H) override;

  /// The deformable tets it evaluates (all of them, or this rank's share), ascending.
  const std::vector<Index>& deformable_tets() const { return active_; }
  const Tets& tets() const { return tets_; }
  /// The laws of deformable_tets(), in that order.
  const std::vector<material::MaterialPtr>& materials() const { return material_; }
  /// The rest shapes of deformable_tets(), in that order.
  const std::vector<TetRestShape>& rest_shapes() const { return rest_; }

 private:
  /// Tets whose element Hessians add_hessian holds at once (4.7 MB; measured in docs/solver.md).
  static constexpr std::size_t kHessianChunk = 4096;

  const Tets& tets_;
  std::vector<material::MaterialPtr> material_;  // per deformable tet, in active_'s order
  std::vector<TetRestShape> rest_;               // per deformable tet, in active_'s order
  std::vector<Index> active_;                    // deformable tets it evaluates
  std::vector<bool> deformable_;                 // per tet, for a share's whole pattern (empty otherwise)
  bool project_hessians_ = false;  // ElasticEnergyOptions::project_hessians
  Index num_nodes_ = 0;
  // node -> (active tet slot * 4 + local node) for race-free gathering, CSR, ascending per node
  std::vector<Index> incidence_offsets_, incidence_;
  // the nodes of each chunk of kHessianChunk active tets (add_hessian), CSR, ascending per chunk
  std::vector<Index> chunk_node_offsets_, chunk_nodes_;
  std::vector<Index> block_index_;  // 16 per active tet, row-major (i, j)
  std::uint64_t bound_version_ = 0;
};

/// Per-tet measures for output: J = det F, and the von Mises equivalent of the Cauchy
/// stress (stress unit). Tets that `elastic` does not hold (rigid tets; on several ranks, those of
/// another rank's share) get J = 1 and zero stress.
struct TetMeasures {
  VectorX J;
  VectorX von_mises;
};
/// The measures of every tet of `elastic`'s mesh (#T) at positions x (#V x 3), computed for
/// deformable_tets().
TetMeasures compute_tet_measures(const Positions& x, const ElasticEnergy& elastic);

}  // namespace sinew::fem
