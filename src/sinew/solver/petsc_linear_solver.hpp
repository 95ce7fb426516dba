#pragma once
/// @file petsc_linear_solver.hpp
/// PETSc's linear solvers for the Newton systems, on one process (docs/solver.md, "PETSc solvers"):
/// - petsc-gamg: conjugate gradients preconditioned by smoothed-aggregation algebraic multigrid
///   (GAMG) given the rigid-body modes as its near-null space: memory and time that grow about
///   linearly with the mesh, for meshes whose Cholesky factor no longer fits;
/// - petsc-mumps: MUMPS's sparse LDL^T, a direct solver that also reports the matrix's inertia
///   (how many negative eigenvalues the tangent has).
/// PETSc is initialized on first use (reading PETSc options from the PETSC_OPTIONS environment
/// variable) and finalized at exit.

#include <memory>

#include "sinew/solver/linear_solver.hpp"

namespace sinew::solver {

/// options.kind must be PetscGamg or PetscMumps.
std::unique_ptr<LinearSolver> make_petsc_linear_solver(const LinearSolverOptions& options);

/// GAMG's near-null space at this process's rows: the rigid-body modes of the listed `unknowns`
/// (#unknowns x up to 6, row i for unknowns[i]) from `motions`. On one process `unknowns` lists
/// them all, and the result is fem::orthonormal_basis of their motions. On several MPI ranks each
/// lists the rows it holds and fits only those: two rounds of a Gram matrix summed over the ranks
/// (fem::orthonormalizing_transform) make the ranks' rows together one orthonormal basis, so that
/// no rank holds the whole modes (docs/mpi.md). Collective on several ranks.
MatrixX rigid_body_modes_of_rows(const LinearSolver::RigidBodyMotions& motions, const std::vector<Index>& unknowns);

}  // namespace sinew::solver
