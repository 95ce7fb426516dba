#include "sinew/fem/hessian_reduction.hpp"

#include <algorithm>
#include <stdexcept>

namespace sinew::fem {
namespace {

/// The unknowns of one node (see DofMap).
struct NodeDofs {
  int ndof = 0;
  Index dof = 0;
  DofMap::NodeKind kind = DofMap::NodeKind::Free;
};

NodeDofs node_dofs(const DofMap& dofs, Index a) { return {dofs.num_node_dofs(a), dofs.first_dof(a), dofs.kind(a)}; }

}  // namespace

HessianReduction::HessianReduction(const DofMap& dofs) : dofs_(dofs) {}

void HessianReduction::bind(const BlockSparseMatrix& H) {
  const Index num_dofs_ = dofs_.num_dofs();
  const auto& offsets = H.row_offsets();
  const auto& cols = H.columns();
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(static_cast<std::size_t>(H.num_blocks()) * 9 + static_cast<std::size_t>(num_dofs_));
  for (Index i = 0; i < num_dofs_; ++i) entries.emplace_back(i, i, 0.0);
  for (Index a = 0; a < H.num_nodes(); ++a) {
    const NodeDofs na = node_dofs(dofs_, a);
    if (na.ndof == 0) continue;
    for (Index k = offsets[a]; k < offsets[a + 1]; ++k) {
      const NodeDofs nb = node_dofs(dofs_, cols[k]);
      for (int i = 0; i < na.ndof; ++i)
        for (int j = 0; j < nb.ndof; ++j) entries.emplace_back(na.dof + i, nb.dof + j, 0.0);
    }
  }
  pattern_.resize(num_dofs_, num_dofs_);
  pattern_.setFromTriplets(entries.begin(), entries.end());  // duplicates summed: pattern only
  pattern_.makeCompressed();

  auto value_index = [&](Index row, Index col) -> Index {
    const int* begin = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[col];
    const int* end = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[col + 1];
    const int* it = std::lower_bound(begin, end, row);
    return static_cast<Index>(it - pattern_.innerIndexPtr());
  };
  block_target_offset_.assign(static_cast<std::size_t>(H.num_blocks()) + 1, 0);
  targets_.clear();
  for (Index a = 0; a < H.num_nodes(); ++a) {
    const NodeDofs na = node_dofs(dofs_, a);
    for (Index k = offsets[a]; k < offsets[a + 1]; ++k) {
      const NodeDofs nb = node_dofs(dofs_, cols[k]);
      if (na.ndof > 0 && nb.ndof > 0)
        for (int i = 0; i < na.ndof; ++i)
          for (int j = 0; j < nb.ndof; ++j) targets_.push_back(value_index(na.dof + i, nb.dof + j));
      block_target_offset_[k + 1] = static_cast<Index>(targets_.size());
    }
  }
  diagonal_target_.resize(static_cast<std::size_t>(num_dofs_));
  for (Index i = 0; i < num_dofs_; ++i) diagonal_target_[i] = value_index(i, i);
  bound_version_ = H.pattern_version();
}

void HessianReduction::reduce(const State& state, const BlockSparseMatrix& H, const NodalVectors& g,
                              const VectorX& node_viscosity, SparseMatrix& K) const {
  const Index num_dofs_ = dofs_.num_dofs();
  if (bound_version_ != H.pattern_version()) throw std::logic_error("HessianReduction::reduce: bind() was not called for this pattern");  // a programming error
  if (K.nonZeros() != pattern_.nonZeros() || K.rows() != num_dofs_) K = pattern_;
  double* values = K.valuePtr();
  std::fill(values, values + K.nonZeros(), 0.0);

  const auto& offsets = H.row_offsets();
  const auto& cols = H.columns();
  const auto& blocks = H.values();
  const Index n = H.num_nodes();
  // Node Jacobians, computed once per node.
  std::vector<Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 6>> jac(static_cast<std::size_t>(n));
  std::vector<char> identity(static_cast<std::size_t>(n), 0);
  for (Index a = 0; a < n; ++a) {
    if (dofs_.num_node_dofs(a) == 0) continue;
    identity[a] = dofs_.kind(a) == DofMap::NodeKind::Free;
    if (!identity[a]) jac[a] = dofs_.node_jacobian(state, a);
  }
  for (Index a = 0; a < n; ++a) {
    const NodeDofs na = node_dofs(dofs_, a);
    if (na.ndof == 0) continue;
    for (Index k = offsets[a]; k < offsets[a + 1]; ++k) {
      const Index b = cols[k];
      const NodeDofs nb = node_dofs(dofs_, b);
      if (nb.ndof == 0) continue;
      const Index* target = targets_.data() + block_target_offset_[k];
      if (identity[a] && identity[b]) {
        const Matrix3& M = blocks[k];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) values[target[3 * i + j]] += M(i, j);
      } else {
        // Products of at most 6 x 3, 3 x 3 and 3 x 6 matrices, coefficient by coefficient
        // (Eigen's general matrix product would block and pack these dynamic-sized operands).
        using NodeJacobian = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 6>;
        const NodeJacobian Ja = identity[a] ? NodeJacobian(Matrix3::Identity()) : jac[a];
        const NodeJacobian Jb = identity[b] ? NodeJacobian(Matrix3::Identity()) : jac[b];
        const Eigen::Matrix<double, Eigen::Dynamic, 3, 0, 6, 3> JaM = Ja.transpose().lazyProduct(blocks[k]);
        const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6> M = JaM.lazyProduct(Jb);
        for (int i = 0; i < na.ndof; ++i)
          for (int j = 0; j < nb.ndof; ++j) values[target[nb.ndof * i + j]] += M(i, j);
      }
    }
  }
  // Second-order term of the rotation map: sum_a [sym(g_a arm_a^T) - (g_a . arm_a) I] on the
  // rotation block (x_a = exp([w]x) arm_a + ..., expanded to second order in w).
  for (std::size_t r = 0; r < dofs_.num_rigid_bodies(); ++r) {
    const Index rotation = dofs_.rigid_first_dof(r) + 3;
    if (rotation < 3) continue;  // not a free body
    Matrix3 G = Matrix3::Zero();
    for (Index a : dofs_.rigid_members(r)) {
      const Vector3 arm = state.x.row(a).transpose() - (dofs_.rigid_center(r) + state.rigid[r].t);
      const Vector3 ga = g.row(a).transpose();
      G += 0.5 * (ga * arm.transpose() + arm * ga.transpose()) - ga.dot(arm) * Matrix3::Identity();
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const Index row = rotation + i, col = rotation + j;
        const int* begin = K.innerIndexPtr() + K.outerIndexPtr()[col];
        const int* end = K.innerIndexPtr() + K.outerIndexPtr()[col + 1];
        values[std::lower_bound(begin, end, row) - K.innerIndexPtr()] += G(i, j);
      }
  }
  if (node_viscosity.size() == n) {
    for (Index a = 0; a < n; ++a) {
      const NodeDofs na = node_dofs(dofs_, a);
      if (na.kind != DofMap::NodeKind::Free && na.kind != DofMap::NodeKind::Planar) continue;
      for (int i = 0; i < na.ndof; ++i) values[diagonal_target_[na.dof + i]] += node_viscosity[a];
    }
  }
}

}  // namespace sinew::fem
