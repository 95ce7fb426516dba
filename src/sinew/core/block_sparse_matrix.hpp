#pragma once
/// @file block_sparse_matrix.hpp
/// A symmetric matrix over nodes stored as 3x3 blocks in CSR order (both (a,b) and (b,a) are
/// stored). Its pattern is set once and reused across Newton iterations: energies add values
/// into existing blocks; a new pattern (e.g. new contact pairs) bumps pattern_version().

#include <cstdint>
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
  /// Changed by every set_pattern(), to a number no other matrix's pattern has had; consumers
  /// cache index maps against it. 0 before the first set_pattern().
  std::uint64_t pattern_version() const { return version_; }
  /// The pattern_version() before the last set_pattern() (0 if none).
  std::uint64_t previous_pattern_version() const { return previous_version_; }
  /// When the last set_pattern() kept every block of the pattern before it (new contact pairs
  /// only add blocks), the new index of each of those blocks (#blocks before); else empty. A
  /// consumer bound to previous_pattern_version() can rebind by this map instead of by find().
  const std::vector<Index>& moved_block_index() const { return moved_block_index_; }

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
  std::uint64_t previous_version_ = 0;
  std::vector<Index> moved_block_index_;
  std::vector<Index> row_offsets_{0};
  std::vector<Index> columns_;
  std::vector<Matrix3> values_;
};

}  // namespace sinew
