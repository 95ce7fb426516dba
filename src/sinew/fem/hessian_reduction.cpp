#include "sinew/fem/hessian_reduction.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

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
  // Every node's unknowns are a contiguous range [first_dof, first_dof + ndof), and two nodes'
  // ranges are equal (members of one rigid body) or disjoint. So K's pattern is made of whole
  // ranges: the rows of one range have the same columns, the union of the ranges of the nodes
  // that any of its nodes has a block with. K is symmetric (H's pattern is), so these rows are
  // also its columns.
  const Index num_dofs = dofs_.num_dofs();
  const auto& offsets = H.row_offsets();
  const auto& cols = H.columns();
  const auto dof_count = static_cast<std::size_t>(num_dofs);

  // The nodes of each range, by the range's first unknown (a counting sort).
  std::vector<Index> range_size(dof_count, 0);  // ndof at a range's first unknown, else 0
  std::vector<Index> member_offset(dof_count + 1, 0);
  for (Index a = 0; a < H.num_nodes(); ++a) {
    const NodeDofs na = node_dofs(dofs_, a);
    if (na.ndof == 0) continue;
    range_size[static_cast<std::size_t>(na.dof)] = na.ndof;
    ++member_offset[static_cast<std::size_t>(na.dof) + 1];
  }
  for (std::size_t d = 0; d < dof_count; ++d) member_offset[d + 1] += member_offset[d];
  std::vector<Index> members(static_cast<std::size_t>(member_offset[dof_count]));
  {
    std::vector<Index> next(member_offset.begin(), member_offset.end() - 1);
    for (Index a = 0; a < H.num_nodes(); ++a) {
      const NodeDofs na = node_dofs(dofs_, a);
      if (na.ndof > 0) members[static_cast<std::size_t>(next[static_cast<std::size_t>(na.dof)]++)] = a;
    }
  }

  // Each row's columns: its range's neighbour ranges, sorted, expanded. An unknown that no node
  // uses (a rigid body without members) keeps its diagonal entry alone.
  std::vector<int> outer(dof_count + 1, 0);
  std::vector<int> inner;
  inner.reserve(static_cast<std::size_t>(H.num_blocks()) * 9 + dof_count);
  std::vector<Index> seen(dof_count, -1);  // the last range that listed a neighbour range
  std::vector<std::pair<Index, Index>> neighbours;  // (first unknown, ndof)
  std::vector<int> row;                             // one row's columns
  for (Index d = 0; d < num_dofs;) {
    const auto D = static_cast<std::size_t>(d);
    const Index ndof = range_size[D] > 0 ? range_size[D] : 1;
    neighbours.assign(1, {d, ndof});
    seen[D] = d;
    for (Index m = member_offset[D]; m < member_offset[D + 1]; ++m) {
      const Index a = members[static_cast<std::size_t>(m)];
      for (Index k = offsets[a]; k < offsets[a + 1]; ++k) {
        const NodeDofs nb = node_dofs(dofs_, cols[k]);
        if (nb.ndof == 0 || seen[static_cast<std::size_t>(nb.dof)] == d) continue;
        seen[static_cast<std::size_t>(nb.dof)] = d;
        neighbours.emplace_back(nb.dof, nb.ndof);
      }
    }
    std::sort(neighbours.begin(), neighbours.end());
    row.clear();
    for (const auto& [first, count] : neighbours)
      for (Index j = 0; j < count; ++j) row.push_back(static_cast<int>(first + j));
    for (Index i = 0; i < ndof; ++i) {
      inner.insert(inner.end(), row.begin(), row.end());
      outer[D + static_cast<std::size_t>(i) + 1] = static_cast<int>(inner.size());
    }
    d += ndof;
  }
  pattern_outer_ = std::move(outer);
  pattern_inner_ = std::move(inner);

  // Where each block entry goes: the rows of a's range are contiguous in every column of b's
  // range, at the same place in each, so one search per block finds them all.
  const int* outer_ptr = pattern_outer_.data();
  const int* inner_ptr = pattern_inner_.data();
  auto value_index = [&](Index row, Index col) -> Index {
    const int* begin = inner_ptr + outer_ptr[col];
    const int* end = inner_ptr + outer_ptr[col + 1];
    return static_cast<Index>(std::lower_bound(begin, end, row) - inner_ptr);
  };
  block_target_offset_.assign(static_cast<std::size_t>(H.num_blocks()) + 1, 0);
  targets_.clear();
  targets_.reserve(static_cast<std::size_t>(H.num_blocks()) * 9);
  for (Index a = 0; a < H.num_nodes(); ++a) {
    const NodeDofs na = node_dofs(dofs_, a);
    for (Index k = offsets[a]; k < offsets[a + 1]; ++k) {
      const NodeDofs nb = node_dofs(dofs_, cols[k]);
      if (na.ndof > 0 && nb.ndof > 0) {
        const Index within_column = value_index(na.dof, nb.dof) - outer_ptr[nb.dof];
        for (int i = 0; i < na.ndof; ++i)
          for (int j = 0; j < nb.ndof; ++j) targets_.push_back(outer_ptr[nb.dof + j] + within_column + i);
      }
      block_target_offset_[k + 1] = static_cast<Index>(targets_.size());
    }
  }
  diagonal_target_.resize(dof_count);
  for (Index i = 0; i < num_dofs; ++i) diagonal_target_[i] = value_index(i, i);
  bound_version_ = H.pattern_version();
}

void HessianReduction::reduce(const State& state, const BlockSparseMatrix& H, const NodalVectors& g,
                              const VectorX& node_viscosity, SparseMatrix& K) const {
  const Index num_dofs_ = dofs_.num_dofs();
  if (bound_version_ != H.pattern_version()) throw std::logic_error("HessianReduction::reduce: bind() was not called for this pattern");  // a programming error
  const auto nonzeros = static_cast<Index>(pattern_inner_.size());
  const bool has_pattern = K.rows() == num_dofs_ && K.cols() == num_dofs_ && K.isCompressed() &&
                           K.nonZeros() == nonzeros &&
                           std::equal(pattern_outer_.begin(), pattern_outer_.end(), K.outerIndexPtr()) &&
                           std::equal(pattern_inner_.begin(), pattern_inner_.end(), K.innerIndexPtr());
  if (!has_pattern) {
    K.resize(num_dofs_, num_dofs_);  // compressed, empty
    K.resizeNonZeros(nonzeros);
    std::copy(pattern_outer_.begin(), pattern_outer_.end(), K.outerIndexPtr());
    std::copy(pattern_inner_.begin(), pattern_inner_.end(), K.innerIndexPtr());
  }
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
