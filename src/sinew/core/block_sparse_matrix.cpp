#include "sinew/core/block_sparse_matrix.hpp"

#include <algorithm>
#include <atomic>

namespace sinew {

void BlockSparseMatrix::set_pattern(Index num_nodes, std::vector<std::pair<Index, Index>> pairs) {
  // Bucketed by row (each pair in both orders, plus the diagonal), then each row sorted and
  // deduplicated: the same pattern as sorting the whole list, at the cost of sorting short rows.
  const auto rows = static_cast<std::size_t>(num_nodes);
  std::vector<Index> count(rows + 1, 0);
  for (const auto& [a, b] : pairs) {
    ++count[static_cast<std::size_t>(a) + 1];
    ++count[static_cast<std::size_t>(b) + 1];
  }
  for (std::size_t a = 0; a < rows; ++a) count[a + 1] += count[a] + 1;  // + the diagonal block
  std::vector<Index> next(count.begin(), count.end() - 1);
  std::vector<Index> columns(static_cast<std::size_t>(count[rows]));
  for (Index a = 0; a < num_nodes; ++a) columns[static_cast<std::size_t>(next[static_cast<std::size_t>(a)]++)] = a;
  for (const auto& [a, b] : pairs) {
    columns[static_cast<std::size_t>(next[static_cast<std::size_t>(a)]++)] = b;
    columns[static_cast<std::size_t>(next[static_cast<std::size_t>(b)]++)] = a;
  }
  pairs.clear();
  pairs.shrink_to_fit();

  std::vector<Index> old_offsets = std::move(row_offsets_), old_columns = std::move(columns_);
  const bool had_pattern = version_ != 0 && num_nodes_ == num_nodes;
  num_nodes_ = num_nodes;
  row_offsets_.assign(rows + 1, 0);
  columns_.clear();
  columns_.reserve(columns.size());
  for (std::size_t a = 0; a < rows; ++a) {
    const auto begin = columns.begin() + count[a], end = columns.begin() + count[a + 1];
    std::sort(begin, end);
    columns_.insert(columns_.end(), begin, std::unique(begin, end));
    row_offsets_[a + 1] = static_cast<Index>(columns_.size());
  }
  values_.assign(columns_.size(), Matrix3::Zero());

  // Where the old blocks went: both patterns' rows are sorted, so one merge per row.
  moved_block_index_.clear();
  if (had_pattern) {
    moved_block_index_.resize(old_columns.size());
    bool kept_all = true;
    for (Index a = 0; a < num_nodes && kept_all; ++a) {
      Index k = row_offsets_[a];
      for (Index old = old_offsets[a]; old < old_offsets[a + 1]; ++old) {
        while (k < row_offsets_[a + 1] && columns_[k] < old_columns[old]) ++k;
        if (k == row_offsets_[a + 1] || columns_[k] != old_columns[old]) {
          kept_all = false;
          break;
        }
        moved_block_index_[old] = k;
      }
    }
    if (!kept_all) moved_block_index_.clear();
  }
  static std::atomic<std::uint64_t> patterns_set{0};
  previous_version_ = version_;
  version_ = ++patterns_set;
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
