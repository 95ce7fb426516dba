#pragma once
/// @file block_sparse_matrix.hpp
/// A symmetric matrix over nodes stored as 3x3 blocks in CSR order (both (a,b) and (b,a) are
/// stored). Its pattern is set once and reused across Newton iterations: energies add values
/// into existing blocks; a new pattern (e.g. new contact pairs) bumps pattern_version().

#include <utility>
#include <vector>

#include "sinew/core/types.hpp"

namespace sinew {

class BlockSparseMatrix {
 public:
  /// Sets the pattern to the given node pairs plus every diagonal block; pairs are made
  /// symmetric and deduplicated. Values are zeroed.
  void set_pattern(Index num_nodes, std::vector<std::pair<Index, Index>> pairs);

  Index num_nodes() const { return num_nodes_; }
  Index num_blocks() const { return static_cast<Index>(columns_.size()); }
  /// Incremented by every set_pattern(); consumers cache index maps against it.
  std::uint64_t pattern_version() const { return version_; }

  /// Block index of (a, b) or -1 when the pattern has no such block. O(log row length).
  Index find(Index a, Index b) const;

  void set_zero();
  /// values[k] += M; k from find(). Not thread-safe for equal k.
  void add(Index k, const Matrix3& M) { values_[static_cast<std::size_t>(k)] += M; }

  /// CSR structure: blocks of row a are [row_offsets[a], row_offsets[a+1]); their columns.
  const std::vector<Index>& row_offsets() const { return row_offsets_; }
  const std::vector<Index>& columns() const { return columns_; }
  const std::vector<Matrix3>& values() const { return values_; }
  std::vector<Matrix3>& values() { return values_; }

  /// y = H v, v and y of length 3 #nodes (node-major).
  VectorX multiply(const VectorX& v) const;
  /// Dense copy (tests only), 3n x 3n.
  MatrixX to_dense() const;

 private:
  Index num_nodes_ = 0;
  std::uint64_t version_ = 0;
  std::vector<Index> row_offsets_{0};
  std::vector<Index> columns_;
  std::vector<Matrix3> values_;
};

}  // namespace sinew
