#include "parallel_run.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "sinew/core/error.hpp"
#include "sinew/core/log.hpp"
#include "sinew/io/atomic_file.hpp"
#include "sinew/parallel/ranks.hpp"

namespace sinew::app {

void start_ranks() {
  parallel::start();
  if (parallel::size() > 1) {
    // OpenBLAS's own setter when it is the BLAS this process loaded (Debian's alternatives may
    // give another, which then keeps its setting).
    using SetThreads = void (*)(int);
    if (auto* set_threads = reinterpret_cast<SetThreads>(::dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
      set_threads(1);
  }
  if (parallel::is_root()) return;
  logger().set_level(spdlog::level::off);
  io::set_files_written(false);
  // What a command prints (schema, a validation's report) comes once, from rank 0.
  if (!std::freopen("/dev/null", "w", stdout)) logger().debug("standard output stays open");
}

int threads_per_rank() {
  if (parallel::size() <= 1) return 0;
  int ranks_here = 0;
  for (const char* name : {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS", "MPICH_LOCALNRANKS"}) {
    if (const char* text = std::getenv(name)) {
      ranks_here = std::atoi(text);
      if (ranks_here > 0) break;
    }
  }
  if (ranks_here <= 0) ranks_here = parallel::size();  // unknown: as if all were on this node
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, cores / ranks_here);
}

void check_ranks_agree(const fem::State& state, double t, int step) {
  if (parallel::size() <= 1) return;
  // Position-weighted so that a permutation of the same values does not pass.
  double checksum = t;
  for (Index a = 0; a < state.x.rows(); ++a) checksum += static_cast<double>(a % 97 + 1) * state.x.row(a).sum();
  const double highest = parallel::max(checksum), lowest = -parallel::max(-checksum);
  if (highest != lowest)
    throw Error(fmt::format("the MPI ranks' states differ after step {} (checksums {:.17g} and {:.17g}): every rank "
                            "must compute the same run; please report it with the scene and the number of ranks",
                            step, lowest, highest));
}

void log_failure(const std::string& message, bool every_rank_saw_it) {
  if (parallel::is_root()) {
    logger().error("{}", message);
  } else if (!every_rank_saw_it) {
    // The other ranks' logger is off: this rank's own failure goes to standard error.
    fmt::print(stderr, "[error] rank {} of {}: {}\n", parallel::rank(), parallel::size(), message);
  }
}

void end_ranks_after_failure(int exit_code, bool every_rank_saw_it) {
  if (parallel::size() > 1 && !every_rank_saw_it) {
    std::fflush(stderr);
    parallel::abort_all(exit_code);
  }
}

}  // namespace sinew::app
