#pragma once
/// @file ranks.hpp
/// The processes of one run. `mpirun -n N sinew ...` starts N copies of the program (ranks);
/// each builds the same model, shares the element work and sums it with the others (docs/mpi.md).
/// A program started without mpirun (or with N = 1) is one rank and never starts MPI: every
/// function here is then a no-op that returns its argument.

#include <cstddef>
#include <string>
#include <vector>

#include "sinew/core/share.hpp"

namespace sinew::parallel {

/// Starts MPI when this process was launched by mpirun (or another MPI launcher) with more than
/// one process; idempotent, cheap when there is nothing to start. MPI is finalized at exit.
/// Throws sinew::Error when MPI cannot start.
void start();

/// This process's rank (0 when MPI was not started).
int rank();
/// Number of ranks (1 when MPI was not started).
int size();
/// True when this process is rank 0, the one that writes outputs and logs.
inline bool is_root() { return rank() == 0; }
/// The number of processes the launcher reports through its environment (OpenMPI, MPICH, PMIx;
/// Slurm's srun through its PMI plugin), 1 when none: what start() goes by. Not SLURM_NTASKS,
/// which a batch script also has where it starts one plain process.
int launched_size();

/// In place, on every rank: values[i] = the sum over ranks of values[i] (n doubles).
void sum(double* values, std::size_t n);
/// The sum of `value` over the ranks.
double sum(double value);
/// The largest `value` of any rank.
double max(double value);
/// True when `value` is true on every rank.
bool all(bool value);
/// True when `value` is true on some rank.
bool any(bool value);
/// `value` of rank 0, on every rank.
int broadcast(int value);
/// `text` of rank 0, on every rank (rank 0's text under 2^31 bytes: MPI's int counts).
std::string broadcast(const std::string& text);
/// Every rank's `bytes` (a different length on each rank allowed), concatenated in rank order,
/// on every rank. Throws sinew::Error on every rank when the total passes 2^31 - 1 bytes (MPI's
/// int counts).
std::vector<char> gather_all(const std::vector<char>& bytes);
/// Waits until every rank has come here.
void barrier();
/// Ends every rank of the run with exit code `code` (a failure on one rank would leave the
/// others waiting for it forever). Returns normally only when MPI was not started.
void abort_all(int code);

/// This rank's share of `count` work items (share_of with this rank of all ranks).
ItemRange my_share(std::size_t count);

}  // namespace sinew::parallel
