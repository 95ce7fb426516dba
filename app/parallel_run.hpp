#pragma once
/// @file parallel_run.hpp
/// What the command does differently on several MPI ranks (docs/mpi.md): rank 0 checks and
/// locks the output directory, writes every file and logs; the other ranks compute the same
/// run silently. A failure that only one rank can see is made every rank's, so no rank waits
/// for another that has stopped.

#include <string>

#include "sinew/fem/state.hpp"

namespace sinew::app {

/// Starts MPI when mpirun launched several ranks (parallel::start) and silences every rank but
/// 0: no log, no standard output, no files. On several ranks OpenBLAS (CHOLMOD's dense kernels) gets one thread per
/// rank: its idle threads would spin on the cores the other ranks compute on. Nothing happens
/// in a process launched alone.
void start_ranks();

/// Worker threads for each rank when the command line does not say: on several ranks the
/// node's cores shared among the ranks on it (at least 1), else 0 (all cores).
int threads_per_rank();

/// Ends the run after a failure: on several ranks, when the failure may be this rank's alone
/// (`every_rank_saw_it` false), it ends every rank with `exit_code` (MPI_Abort); otherwise, and
/// on one rank, it returns and the caller exits with `exit_code`.
void end_ranks_after_failure(int exit_code, bool every_rank_saw_it);

/// On several ranks: throws sinew::Error when the ranks' states differ after step `step` (every
/// rank must compute the same run; a difference would end in ranks waiting for each other).
/// Compares a checksum of the positions and the load parameter or time `t`.
void check_ranks_agree(const fem::State& state, double t, int step);

/// Logs an error: on rank 0 always; on another rank only when `every_rank_saw_it` is false (rank
/// 0's log has the others), with the rank named.
void log_failure(const std::string& message, bool every_rank_saw_it);

}  // namespace sinew::app
