#include "sinew/parallel/petsc.hpp"

#include <cstdlib>
#include <mutex>

#include <fmt/format.h>
#ifdef SINEW_SANITIZER_BUILD
#include <sanitizer/lsan_interface.h>
#endif

#include "sinew/core/error.hpp"
#include "sinew/parallel/ranks.hpp"

namespace sinew::parallel {

void check_petsc(PetscErrorCode code, const char* call) {
  if (code == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  if (code == PETSC_ERR_MEM) throw OutOfMemoryError(fmt::format("PETSc ran out of memory in {}", call));
  throw Error(fmt::format("PETSc failed in {}: {} (error {})", call, text ? text : "unknown error", static_cast<int>(code)));
}

void ensure_petsc() {
  static std::once_flag once;
  std::call_once(once, [] {
    start();  // MPI first when mpirun started several ranks: PETSc then runs on all of them
    PetscBool initialized = PETSC_FALSE;
    PetscInitialized(&initialized);
    if (initialized) return;
#ifdef SINEW_SANITIZER_BUILD
    // MPI's and PETSc's start-up state lives until the process ends (some of it in plugins MPI
    // unloads): not leaks of ours for LeakSanitizer to report.
    __lsan::ScopedDisabler not_ours;
#endif
    check_petsc(PetscInitializeNoArguments(), "PetscInitializeNoArguments");
    // PETSc's own report is silenced: check_petsc reports the failure with sinew's exceptions.
    check_petsc(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr), "PetscPushErrorHandler");
    std::atexit([] {
#ifdef SINEW_SANITIZER_BUILD
      __lsan::ScopedDisabler not_ours;  // MPI_Finalize's own bookkeeping
#endif
      PetscFinalize();
    });
  });
}

}  // namespace sinew::parallel
