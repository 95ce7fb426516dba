#include "sinew/solver/petsc_linear_solver.hpp"

#include <petscksp.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include <fmt/format.h>

#include "sinew/core/error.hpp"
#include "sinew/parallel/petsc.hpp"
#include "sinew/parallel/ranks.hpp"

namespace sinew::solver {
namespace {

/// PETSc's error codes as exceptions (parallel/petsc.hpp).
void check(PetscErrorCode code, const char* call) { parallel::check_petsc(code, call); }

template <class T, PetscErrorCode (*Destroy)(T*)>
using Handle = parallel::PetscHandle<T, Destroy>;

using MatHandle = Handle<Mat, MatDestroy>;
using KspHandle = Handle<KSP, KSPDestroy>;
using VecHandle = Handle<Vec, VecDestroy>;
using NullSpaceHandle = Handle<MatNullSpace, MatNullSpaceDestroy>;

class PetscSolver final : public LinearSolver {
 public:
  explicit PetscSolver(const LinearSolverOptions& options)
      : gamg_(options.kind == LinearSolverOptions::Kind::PetscGamg),
        tolerance_(options.tolerance),
        max_iterations_(options.max_iterations) {
    parallel::ensure_petsc();
  }

  void analyze(const SparseMatrix& K) override {
    // K is symmetric and stored in full, so its compressed columns are also its compressed rows.
    ksp_.reset();
    A_.reset();
    const auto n = static_cast<PetscInt>(K.rows());
    std::vector<PetscInt> starts(K.outerIndexPtr(), K.outerIndexPtr() + K.outerSize() + 1);
    std::vector<PetscInt> columns(K.innerIndexPtr(), K.innerIndexPtr() + K.nonZeros());
    const bool blocked = block_size_ > 1 && n % block_size_ == 0;
    // On several ranks each owns a contiguous range of rows (whole blocks of 3 when blocked): K is
    // the same on every rank (docs/mpi.md), each gives PETSc its own rows.
    const auto unit = static_cast<std::size_t>(blocked ? block_size_ : 1);
    const ItemRange blocks = parallel::my_share(static_cast<std::size_t>(n) / unit);
    first_row_ = static_cast<PetscInt>(blocks.begin * unit);
    local_rows_ = static_cast<PetscInt>((blocks.end - blocks.begin) * unit);
    check(MatCreate(communicator(), &*A_), "MatCreate");
    check(MatSetSizes(A_.get(), local_rows_, local_rows_, n, n), "MatSetSizes");
    check(MatSetType(A_.get(), distributed() ? MATMPIAIJ : MATSEQAIJ), "MatSetType");
    if (blocked) check(MatSetBlockSize(A_.get(), block_size_), "MatSetBlockSize");
    if (distributed()) {
      std::vector<PetscInt> local_starts(static_cast<std::size_t>(local_rows_) + 1);
      for (PetscInt r = 0; r <= local_rows_; ++r)
        local_starts[static_cast<std::size_t>(r)] = starts[static_cast<std::size_t>(first_row_ + r)] - starts[static_cast<std::size_t>(first_row_)];
      check(MatMPIAIJSetPreallocationCSR(A_.get(), local_starts.data(),
                                         columns.data() + starts[static_cast<std::size_t>(first_row_)], nullptr),
            "MatMPIAIJSetPreallocationCSR");
    } else {
      check(MatSeqAIJSetPreallocationCSR(A_.get(), starts.data(), columns.data(), nullptr), "MatSeqAIJSetPreallocationCSR");
    }
    check(MatSetOption(A_.get(), MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption(MAT_SYMMETRIC)");
    check(MatSetOption(A_.get(), MAT_SYMMETRY_ETERNAL, PETSC_TRUE), "MatSetOption(MAT_SYMMETRY_ETERNAL)");
    check(MatSetOption(A_.get(), MAT_NEW_NONZERO_LOCATION_ERR, PETSC_TRUE), "MatSetOption");
    starts_ = std::move(starts);
    columns_ = std::move(columns);
    check(KSPCreate(communicator(), &*ksp_), "KSPCreate");
    PC pc = nullptr;
    check(KSPGetPC(ksp_.get(), &pc), "KSPGetPC");
    if (gamg_) {
      check(KSPSetType(ksp_.get(), KSPCG), "KSPSetType(cg)");
      check(PCSetType(pc, PCGAMG), "PCSetType(gamg)");
      check(KSPSetTolerances(ksp_.get(), tolerance_, 0.0, PETSC_DEFAULT, max_iterations_), "KSPSetTolerances");
    } else {
      check(KSPSetType(ksp_.get(), KSPPREONLY), "KSPSetType(preonly)");
      check(PCSetType(pc, PCCHOLESKY), "PCSetType(cholesky)");
      check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType(mumps)");
    }
    check(KSPSetOperators(ksp_.get(), A_.get(), A_.get()), "KSPSetOperators");
    if (!gamg_) {
      check(PCFactorSetUpMatSolverType(pc), "PCFactorSetUpMatSolverType");
      Mat F = nullptr;
      check(PCFactorGetMatrix(pc, &F), "PCFactorGetMatrix");
      check(MatMumpsSetIcntl(F, 24, 1), "MatMumpsSetIcntl(24)");  // detect null pivots (the inertia's zeros)
      check(MatMumpsSetIcntl(F, 14, 50), "MatMumpsSetIcntl(14)");  // 50 % workspace headroom
      // The inertia of a distributed factorization needs the root node factorized on one rank
      // (PETSc's MatGetInertia for MUMPS).
      if (distributed()) check(MatMumpsSetIcntl(F, 13, 1), "MatMumpsSetIcntl(13)");
    }
    check(KSPSetFromOptions(ksp_.get()), "KSPSetFromOptions");  // PETSC_OPTIONS may tune either
  }

  bool factorize(const SparseMatrix& K) override {
    if (!A_.get() || !same_pattern(K)) analyze(K);
    if (distributed()) {
      for (PetscInt row = first_row_; row < first_row_ + local_rows_; ++row) {
        const auto begin = starts_[static_cast<std::size_t>(row)], end = starts_[static_cast<std::size_t>(row) + 1];
        check(MatSetValues(A_.get(), 1, &row, end - begin, columns_.data() + begin, K.valuePtr() + begin,
                           INSERT_VALUES),
              "MatSetValues");
      }
    } else {
      PetscScalar* values = nullptr;
      check(MatSeqAIJGetArray(A_.get(), &values), "MatSeqAIJGetArray");
      std::copy(K.valuePtr(), K.valuePtr() + K.nonZeros(), values);
      check(MatSeqAIJRestoreArray(A_.get(), &values), "MatSeqAIJRestoreArray");
    }
    check(MatAssemblyBegin(A_.get(), MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
    check(MatAssemblyEnd(A_.get(), MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
    if (gamg_ && modes_.cols() > 0 && modes_.rows() == K.rows()) {
      std::vector<VecHandle> vectors(static_cast<std::size_t>(modes_.cols()));
      std::vector<Vec> raw;
      for (Index c = 0; c < modes_.cols(); ++c) {
        auto& v = vectors[static_cast<std::size_t>(c)];
        check(VecCreateMPI(communicator(), local_rows_, static_cast<PetscInt>(K.rows()), &*v), "VecCreateMPI");
        PetscScalar* data = nullptr;
        check(VecGetArray(v.get(), &data), "VecGetArray");
        std::copy(modes_.col(c).data() + first_row_, modes_.col(c).data() + first_row_ + local_rows_, data);
        check(VecRestoreArray(v.get(), &data), "VecRestoreArray");
        raw.push_back(v.get());
      }
      NullSpaceHandle space;
      check(MatNullSpaceCreate(communicator(), PETSC_FALSE, static_cast<PetscInt>(raw.size()), raw.data(), &*space),
            "MatNullSpaceCreate");
      check(MatSetNearNullSpace(A_.get(), space.get()), "MatSetNearNullSpace");
    }
    ++factorizations_;
    negative_ = -1;
    check(KSPSetOperators(ksp_.get(), A_.get(), A_.get()), "KSPSetOperators");
    check(KSPSetUp(ksp_.get()), "KSPSetUp");
    PC pc = nullptr;
    check(KSPGetPC(ksp_.get(), &pc), "KSPGetPC");
    PCFailedReason reason = PC_NOERROR;
    check(PCGetFailedReason(pc, &reason), "PCGetFailedReason");
    if (reason == PC_FACTOR_OUTMEMORY)
      throw OutOfMemoryError(fmt::format("MUMPS ran out of memory factorizing a {} x {} matrix", K.rows(), K.rows()));
    if (reason != PC_NOERROR) return false;
    if (gamg_) return true;
    Mat F = nullptr;
    check(PCFactorGetMatrix(pc, &F), "PCFactorGetMatrix");
    PetscInt negative = 0, zero = 0, positive = 0;
    check(MatGetInertia(F, &negative, &zero, &positive), "MatGetInertia");
    negative_ = negative;
    return negative == 0 && zero == 0;  // positive definite: the caller shifts otherwise, as for CHOLMOD
  }

  LinearSolveStats solve(const VectorX& b, VectorX& x) override {
    LinearSolveStats stats;
    x = VectorX::Zero(b.size());
    VecHandle pb, px;
    wrap_local(b, pb);
    wrap_local(x, px);
    check(KSPSolve(ksp_.get(), pb.get(), px.get()), "KSPSolve");
    KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
    check(KSPGetConvergedReason(ksp_.get(), &reason), "KSPGetConvergedReason");
    PetscInt iterations = 0;
    check(KSPGetIterationNumber(ksp_.get(), &iterations), "KSPGetIterationNumber");
    // Each rank solved for its own rows (the rest of x is 0 there): every rank gets all of x.
    if (distributed()) parallel::sum(x.data(), static_cast<std::size_t>(x.size()));
    stats.iterations = gamg_ ? static_cast<int>(iterations) : 0;
    stats.relative_residual = relative_residual(x, b);
    // CG meeting negative curvature (an indefinite tangent) or stopping short: the caller shifts.
    stats.success = reason > 0 && x.allFinite();
    return stats;
  }

  const char* name() const override {
    return name_of(gamg_ ? LinearSolverOptions::Kind::PetscGamg : LinearSolverOptions::Kind::PetscMumps).data();
  }
  int factorizations() const override { return factorizations_; }
  bool wants_rigid_body_modes() const override { return gamg_; }
  void set_rigid_body_modes(const MatrixX& modes, int block_size) override {
    modes_ = modes;
    if (block_size != block_size_) {
      block_size_ = block_size;
      A_.reset();  // the block size is set before preallocation: rebuild on the next factorize
      ksp_.reset();
    }
  }
  long negative_eigenvalues() const override { return negative_; }

 private:
  bool same_pattern(const SparseMatrix& K) const {
    return starts_.size() == static_cast<std::size_t>(K.outerSize() + 1) &&
           columns_.size() == static_cast<std::size_t>(K.nonZeros()) &&
           std::equal(starts_.begin(), starts_.end(), K.outerIndexPtr()) &&
           std::equal(columns_.begin(), columns_.end(), K.innerIndexPtr());
  }

  /// |A x - b| / |b| with PETSc's matrix (the one factorized; the caller's K may be gone).
  double relative_residual(const VectorX& x, const VectorX& b) const {
    VectorX Ax = VectorX::Zero(b.size());
    VecHandle px, pAx;
    wrap_local(x, px);
    wrap_local(Ax, pAx);
    check(MatMult(A_.get(), px.get(), pAx.get()), "MatMult");
    const auto rows = Eigen::seqN(first_row_, local_rows_);
    double squares[2] = {(Ax(rows) - b(rows)).squaredNorm(), b(rows).squaredNorm()};
    if (distributed()) parallel::sum(squares, 2);
    const double nb = std::sqrt(squares[1]);
    return nb > 0 ? std::sqrt(squares[0]) / nb : std::sqrt(squares[0]);
  }

  /// The ranks share the matrix (a run on several MPI ranks, docs/mpi.md).
  static bool distributed() { return parallel::size() > 1; }
  static MPI_Comm communicator() { return distributed() ? PETSC_COMM_WORLD : PETSC_COMM_SELF; }

  /// A PETSc vector viewing this rank's rows of an Eigen vector of all rows (no copy; PETSc
  /// writes into it when it is a solution).
  void wrap_local(const VectorX& v, VecHandle& out) const {
    out.reset();
    const auto n = static_cast<PetscInt>(v.size());
    if (distributed())
      check(VecCreateMPIWithArray(communicator(), 1, local_rows_, n, v.data() + first_row_, &*out),
            "VecCreateMPIWithArray");
    else
      check(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, v.data(), &*out), "VecCreateSeqWithArray");
  }

  bool gamg_;
  double tolerance_;
  int max_iterations_;
  int block_size_ = 1;
  MatrixX modes_;
  MatHandle A_;
  KspHandle ksp_;
  PetscInt first_row_ = 0;         ///< this rank's rows of the matrix: [first_row_, first_row_ + local_rows_)
  PetscInt local_rows_ = 0;
  std::vector<PetscInt> starts_;   ///< the analyzed pattern's column starts
  std::vector<PetscInt> columns_;  ///< and row indices (compressed columns of the symmetric K)
  int factorizations_ = 0;
  long negative_ = -1;
};

}  // namespace

std::unique_ptr<LinearSolver> make_petsc_linear_solver(const LinearSolverOptions& options) {
  return std::make_unique<PetscSolver>(options);
}

}  // namespace sinew::solver
