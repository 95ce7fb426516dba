#include "sinew/core/block_sparse_matrix.hpp"

#include <algorithm>

namespace sinew {

void BlockSparseMatrix::set_pattern(Index num_nodes, std::vector<std::pair<Index, Index>> pairs) {
  const std::size_t n = pairs.size();
  pairs.reserve(2 * n + static_cast<std::size_t>(num_nodes));
  for (std::size_t i = 0; i < n; ++i) pairs.emplace_back(pairs[i].second, pairs[i].first);
  for (Index a = 0; a < num_nodes; ++a) pairs.emplace_back(a, a);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());

  num_nodes_ = num_nodes;
  row_offsets_.assign(static_cast<std::size_t>(num_nodes) + 1, 0);
  columns_.resize(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    ++row_offsets_[static_cast<std::size_t>(pairs[k].first) + 1];
    columns_[k] = pairs[k].second;
  }
  for (Index a = 0; a < num_nodes; ++a) row_offsets_[a + 1] += row_offsets_[a];
  values_.assign(pairs.size(), Matrix3::Zero());
  ++version_;
}

Index BlockSparseMatrix::find(Index a, Index b) const {
  const auto begin = columns_.begin() + row_offsets_[a];
  const auto end = columns_.begin() + row_offsets_[a + 1];
  const auto it = std::lower_bound(begin, end, b);
  if (it == end || *it != b) return -1;
  return static_cast<Index>(it - columns_.begin());
}

void BlockSparseMatrix::set_zero() {
  for (auto& M : values_) M.setZero();
}

VectorX BlockSparseMatrix::multiply(const VectorX& v) const {
  VectorX y = VectorX::Zero(3 * num_nodes_);
  for (Index a = 0; a < num_nodes_; ++a) {
    Vector3 acc = Vector3::Zero();
    for (Index k = row_offsets_[a]; k < row_offsets_[a + 1]; ++k)
      acc += values_[k] * v.segment<3>(3 * columns_[k]);
    y.segment<3>(3 * a) = acc;
  }
  return y;
}

MatrixX BlockSparseMatrix::to_dense() const {
  MatrixX D = MatrixX::Zero(3 * num_nodes_, 3 * num_nodes_);
  for (Index a = 0; a < num_nodes_; ++a)
    for (Index k = row_offsets_[a]; k < row_offsets_[a + 1]; ++k)
      D.block<3, 3>(3 * a, 3 * columns_[k]) += values_[k];
  return D;
}

}  // namespace sinew
