#pragma once
/// @file partition.hpp
/// Which rank owns which tet on a run of several processes (docs/mpi.md, "Who owns what"): the
/// tets' face-adjacency graph cut into compact parts of balanced work by PT-Scotch, through
/// PETSc's MatPartitioning.

#include <vector>

#include "sinew/core/types.hpp"

namespace sinew::parallel {

/// The part (0 .. parts-1) of every tet of `tets` (#T x 4 node indices): a partition of the
/// tets' dual graph (two tets are neighbours when they share a face) that balances the sum of
/// `weights` (#T, each >= 1; empty: 1 each) over the parts and cuts few faces, so each part is
/// a compact region of the mesh. Computed by PT-Scotch through PETSc (MatPartitioning), each rank
/// of the run giving PETSc its contiguous share of the graph's rows: collective, every rank must
/// call it with the same mesh, and every rank gets the same result. With parts <= 1, or fewer
/// tets than parts or ranks, the parts are contiguous ranges of the tets (share_of) instead.
/// The same tets, weights and number of ranks give the same partition on every call and in every
/// run: Scotch runs on one thread (this sets SCOTCH_PTHREAD_NUMBER=1 in the process's
/// environment) with its random generator reset.
/// Throws sinew::Error when `weights` has the wrong size or a weight below 1, or PETSc fails.
std::vector<int> partition_tets(const Tets& tets, const std::vector<int>& weights, int parts);

/// The owner of every node of 0 .. num_nodes-1 given the owner of every tet (#T): the owner of
/// the lowest-numbered tet that uses the node, 0 for a node no tet uses.
std::vector<int> node_owners(const Tets& tets, const std::vector<int>& tet_owner, Index num_nodes);

}  // namespace sinew::parallel
