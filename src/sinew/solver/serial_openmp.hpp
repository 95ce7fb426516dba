#pragma once
/// @file serial_openmp.hpp
/// Runs the OpenMP parallel regions that a library opens from the calling thread on that thread
/// alone, for the lifetime of a scope.
///
/// Why: Debian's CHOLMOD (SuiteSparse 5) opens an OpenMP region with a compiled-in team of four
/// threads (`CHOLMOD_OMP_NUM_THREADS`) for every small scatter of its supernodal factorization.
/// Waking and parking that team costs more than the scatter: on the knee of
/// examples/knee-flexion-hull.json the linear solve took 1.6x longer with it than on one thread
/// (docs/solver.md, "CHOLMOD's OpenMP team").
/// CHOLMOD's dense kernels run in the BLAS, whose own threads this does not touch.
///
/// How: the OpenMP runtime's max-active-levels is set to 0, so every region opened in the scope
/// is inactive (a team of one, the calling thread), and restored when the scope ends. Nothing is
/// compiled with OpenMP here: the header only declares the runtime's functions, and the runtime
/// (libgomp, which CHOLMOD loads anyway) is linked to the solver module.

#include <omp.h>

namespace sinew::solver {

/// While an object lives, OpenMP regions opened by the thread that made it run on that thread
/// only. Not copyable; nests (each restores what it found).
class SerialOpenMpScope {
 public:
  SerialOpenMpScope() : saved_levels_(omp_get_max_active_levels()) { omp_set_max_active_levels(0); }
  ~SerialOpenMpScope() { omp_set_max_active_levels(saved_levels_); }
  SerialOpenMpScope(const SerialOpenMpScope&) = delete;
  SerialOpenMpScope& operator=(const SerialOpenMpScope&) = delete;

 private:
  int saved_levels_;  ///< max-active-levels when the scope began
};

}  // namespace sinew::solver
