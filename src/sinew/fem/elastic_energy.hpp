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
};

class ElasticEnergy final : public Energy {
 public:
  /// `tet_material`: one law per tet (#T), nullptr = rigid/no elastic energy.
  ElasticEnergy(const Positions& rest, const Tets& tets, std::vector<material::MaterialPtr> tet_material,
                ElasticEnergyOptions options = {});

  std::string_view name() const override { return "elastic"; }
  double value(const Positions& x) const override;
  void add_gradient(const Positions& x, NodalVectors& grad) const override;
  void add_hessian(const Positions& x, BlockSparseMatrix& H) const override;
  void hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const override;
  bool is_valid(const Positions& x) const override;

  /// Caches, for every deformable tet, the block indices of its 16 node pairs in H.
  /// Must be called after H's pattern is set and before add_hessian(). When H's pattern grew
  /// from the one bound last, the indices move by H.moved_block_index() (no search).
  void bind_pattern(const BlockSparseMatrix& H) override;

  const std::vector<Index>& deformable_tets() const { return active_; }
  const Tets& tets() const { return tets_; }
  /// Per tet (#T), null for rigid tets and for the tets of another rank's share.
  const std::vector<material::MaterialPtr>& tet_materials() const { return material_; }
  /// The rest shapes of deformable_tets(), in that order.
  const std::vector<TetRestShape>& rest_shapes() const { return rest_; }

 private:
  const Tets& tets_;
  std::vector<material::MaterialPtr> material_;  // per tet
  std::vector<TetRestShape> rest_;               // per deformable tet, in active_'s order
  std::vector<Index> active_;                    // deformable tets
  ElasticEnergyOptions options_;
  Index num_nodes_ = 0;
  // node -> (active tet slot * 4 + local node) for race-free gathering, CSR
  std::vector<Index> incidence_offsets_, incidence_;
  std::vector<Index> block_index_;  // 16 per active tet, row-major (i, j)
  std::uint64_t bound_version_ = 0;
};

/// Per-tet measures for output: J = det F, and the von Mises equivalent of the Cauchy
/// stress (stress unit). Rigid tets get J = 1 and zero stress.
struct TetMeasures {
  VectorX J;
  VectorX von_mises;
};
/// The measures of every tet of `elastic`'s mesh (#T) at positions x (#V x 3).
TetMeasures compute_tet_measures(const Positions& x, const ElasticEnergy& elastic);

}  // namespace sinew::fem
