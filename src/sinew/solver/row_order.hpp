#pragma once
/// @file row_order.hpp
/// Which rows of the Newton matrix each rank holds in a linear solve shared among MPI ranks
/// (docs/mpi.md, "Who owns what"): the unknowns of the nodes a rank owns, so that its rows couple
/// mostly to its own and the matrix's off-rank part is the partition's boundary.

#include <vector>

#include "sinew/core/types.hpp"
#include "sinew/fem/dof_map.hpp"

namespace sinew::solver {

/// The rank owning each of the dofs' unknowns (#unknowns): a node's unknowns go to
/// `node_owner[node]` (#V), a rigid body's six to rank 0. Empty when `node_owner` is empty.
/// Throws sinew::Error when `node_owner` is neither empty nor one per node of `num_nodes`.
std::vector<int> unknown_owners(const fem::DofMap& dofs, const std::vector<int>& node_owner, Index num_nodes);

/// The unknowns renumbered rank by rank: PETSc's rank r holds the rows [first[r], first[r+1]) of
/// the renumbered matrix.
struct RowOrder {
  std::vector<Index> old_of_new;  ///< #unknowns: the unknown at each new position
  std::vector<Index> first;       ///< ranks + 1 offsets; first[0] = 0, first[ranks] = #unknowns
};

/// The unknowns of 0..n-1 ordered by their owner (`owner`: #n ranks in 0..ranks-1), in their old
/// order within a rank, in whole blocks of `block_size` (n a multiple of it; a block goes where its
/// first unknown's owner says). With `owner` empty: the contiguous shares of blocks (share_of).
/// Throws sinew::Error when `owner` has the wrong size or a rank outside 0..ranks-1, or n is not a
/// multiple of `block_size`.
RowOrder order_rows_by_owner(Index n, const std::vector<int>& owner, int ranks, int block_size);

}  // namespace sinew::solver
