#pragma once
/// @file petsc.hpp
/// PETSc, shared by the linear solvers and the mesh partitioner: started once per process (on
/// every MPI rank when mpirun started several), its errors turned into sinew's exceptions, and
/// its objects owned by RAII handles.

#include <petscsys.h>

namespace sinew::parallel {

/// Initializes PETSc (and MPI, as a singleton when not started by mpirun) once per process and
/// finalizes it at exit. PETSc's own error printing is replaced by return codes that
/// check_petsc turns into exceptions.
void ensure_petsc();

/// Throws sinew::Error naming `call` when `code` is not 0 (OutOfMemoryError for PETSc's
/// out-of-memory code), with PETSc's text for the code.
void check_petsc(PetscErrorCode code, const char* call);

/// Owns one PETSc object and destroys it with the matching XxxDestroy.
template <class T, PetscErrorCode (*Destroy)(T*)>
class PetscHandle {
 public:
  PetscHandle() = default;
  PetscHandle(const PetscHandle&) = delete;
  PetscHandle& operator=(const PetscHandle&) = delete;
  ~PetscHandle() { reset(); }
  void reset() {
    if (object_) Destroy(&object_);
    object_ = nullptr;
  }
  T& operator*() { return object_; }
  T get() const { return object_; }

 private:
  T object_ = nullptr;
};

}  // namespace sinew::parallel
