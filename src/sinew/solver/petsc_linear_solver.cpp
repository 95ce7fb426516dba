#include "sinew/solver/petsc_linear_solver.hpp"

#include <petscksp.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "sinew/core/error.hpp"
#include "sinew/core/log.hpp"
#include "sinew/fem/rigid_body_modes.hpp"
#include "sinew/parallel/petsc.hpp"
#include "sinew/parallel/ranks.hpp"
#include "sinew/solver/row_order.hpp"

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
    ++layout_;
    const auto n = static_cast<PetscInt>(K.rows());
    rows_ = n;
    std::vector<PetscInt> starts(K.outerIndexPtr(), K.outerIndexPtr() + K.outerSize() + 1);
    std::vector<PetscInt> columns(K.innerIndexPtr(), K.innerIndexPtr() + K.nonZeros());
    const bool blocked = block_size_ > 1 && n % block_size_ == 0;
    check(MatCreate(communicator(), &*A_), "MatCreate");
    if (distributed()) {
      // Each rank passes its part of K (docs/mpi.md; on a pattern of its own) and holds its own
      // rows: the unknowns of the nodes it owns when set_row_owners said which
      // (whole blocks of 3 when blocked), else a contiguous range. PETSc numbers the rows rank by
      // rank, so K is renumbered by order_.
      const bool owned = owner_.size() == static_cast<std::size_t>(n);
      order_ = order_rows_by_owner(n, owned ? owner_ : std::vector<int>{}, parallel::size(), blocked ? block_size_ : 1);
      const auto me = static_cast<std::size_t>(parallel::rank());
      first_row_ = static_cast<PetscInt>(order_.first[me]);
      local_rows_ = static_cast<PetscInt>(order_.first[me + 1] - order_.first[me]);
      std::vector<PetscInt> new_of_old(static_cast<std::size_t>(n));
      for (PetscInt i = 0; i < n; ++i) new_of_old[static_cast<std::size_t>(order_.old_of_new[static_cast<std::size_t>(i)])] = i;
      // This rank's part of K renumbered (each rank adds its part into every row it touches).
      row_starts_.assign(1, 0);
      row_columns_.clear();
      value_source_.clear();
      std::vector<std::pair<PetscInt, PetscInt>> row;  // (new column, index into K's values)
      for (PetscInt i = 0; i < n; ++i) {
        const auto old = static_cast<std::size_t>(order_.old_of_new[static_cast<std::size_t>(i)]);
        row.clear();
        for (PetscInt k = starts[old]; k < starts[old + 1]; ++k) row.emplace_back(new_of_old[static_cast<std::size_t>(columns[static_cast<std::size_t>(k)])], k);
        std::sort(row.begin(), row.end());
        for (const auto& [column, source] : row) {
          row_columns_.push_back(column);
          value_source_.push_back(source);
        }
        row_starts_.push_back(static_cast<PetscInt>(row_columns_.size()));
      }
      check(MatSetSizes(A_.get(), local_rows_, local_rows_, n, n), "MatSetSizes");
      check(MatSetType(A_.get(), MATMPIAIJ), "MatSetType");
      if (blocked) check(MatSetBlockSize(A_.get(), block_size_), "MatSetBlockSize");
      preallocate_union_of_parts(n, blocked);
      if (!reported_layout_) report_layout(n);
    } else {
      first_row_ = 0;
      local_rows_ = n;
      check(MatSetSizes(A_.get(), n, n, n, n), "MatSetSizes");
      check(MatSetType(A_.get(), MATSEQAIJ), "MatSetType");
      if (blocked) check(MatSetBlockSize(A_.get(), block_size_), "MatSetBlockSize");
      check(MatSeqAIJSetPreallocationCSR(A_.get(), starts.data(), columns.data(), nullptr), "MatSeqAIJSetPreallocationCSR");
    }
    check(MatSetOption(A_.get(), MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption(MAT_SYMMETRIC)");
    check(MatSetOption(A_.get(), MAT_SYMMETRY_ETERNAL, PETSC_TRUE), "MatSetOption(MAT_SYMMETRY_ETERNAL)");
    check(MatSetOption(A_.get(), MAT_NEW_NONZERO_LOCATION_ERR, PETSC_TRUE), "MatSetOption");
    starts_ = std::move(starts);
    // On several ranks the renumbered rows (row_columns_, value_source_) hold the pattern already:
    // a copy of K's row indices would be another 4 bytes per nonzero of this rank's part.
    if (distributed())
      std::vector<PetscInt>().swap(columns_);
    else
      columns_ = std::move(columns);
    check(KSPCreate(communicator(), &*ksp_), "KSPCreate");
    PC pc = nullptr;
    check(KSPGetPC(ksp_.get(), &pc), "KSPGetPC");
    if (gamg_) {
      check(KSPSetType(ksp_.get(), KSPCG), "KSPSetType(cg)");
      check(PCSetType(pc, PCGAMG), "PCSetType(gamg)");
      check(KSPSetTolerances(ksp_.get(), tolerance_, 0.0, PETSC_DEFAULT, max_iterations_), "KSPSetTolerances");
      use_safe_chebyshev_bounds();
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
    // The ranks analyze together (collective), when the part of any of them has changed.
    bool stale = !A_.get() || !same_pattern(K);
    if (distributed()) stale = parallel::any(stale);
    if (stale) analyze(K);
    if (distributed()) {
      // Each rank adds its part of K (Objective::set_hessian_summed): the rows it touches, its own
      // and its neighbours' (PETSc sends those to their holders at assembly); its rows of zeros
      // are left out, so a rank sends little beyond its part of the mesh.
      // A row's values at a time: a copy of all of them would be another 8 bytes per nonzero.
      check(MatZeroEntries(A_.get()), "MatZeroEntries");
      std::vector<PetscScalar> values;
      for (PetscInt row = 0; row < rows_; ++row) {
        const auto begin = row_starts_[static_cast<std::size_t>(row)], end = row_starts_[static_cast<std::size_t>(row) + 1];
        values.resize(static_cast<std::size_t>(end - begin));
        for (PetscInt k = begin; k < end; ++k)
          values[static_cast<std::size_t>(k - begin)] = K.valuePtr()[value_source_[static_cast<std::size_t>(k)]];
        if (std::all_of(values.begin(), values.end(), [](double v) { return v == 0.0; })) continue;
        check(MatSetValues(A_.get(), 1, &row, end - begin, row_columns_.data() + begin, values.data(), ADD_VALUES),
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
    if (gamg_ && motions_) {
      compute_rigid_body_modes();
      motions_ = nullptr;  // its state is gone after this factorization
    }
    if (gamg_ && modes_.cols() > 0 && modes_layout_ == layout_ && modes_.rows() == local_rows_) {
      std::vector<VecHandle> vectors(static_cast<std::size_t>(modes_.cols()));
      std::vector<Vec> raw;
      for (Index c = 0; c < modes_.cols(); ++c) {
        auto& v = vectors[static_cast<std::size_t>(c)];
        check(VecCreateMPI(communicator(), local_rows_, static_cast<PetscInt>(K.rows()), &*v), "VecCreateMPI");
        PetscScalar* data = nullptr;
        check(VecGetArray(v.get(), &data), "VecGetArray");
        std::copy(modes_.col(c).data(), modes_.col(c).data() + local_rows_, data);
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
    const VectorX b_mine = local_part(b);
    VectorX x_mine = VectorX::Zero(local_rows_);
    VecHandle pb, px;
    wrap(b_mine, pb);
    wrap(x_mine, px);
    check(KSPSolve(ksp_.get(), pb.get(), px.get()), "KSPSolve");
    KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
    check(KSPGetConvergedReason(ksp_.get(), &reason), "KSPGetConvergedReason");
    PetscInt iterations = 0;
    check(KSPGetIterationNumber(ksp_.get(), &iterations), "KSPGetIterationNumber");
    x = whole(x_mine, b.size());
    stats.iterations = gamg_ ? static_cast<int>(iterations) : 0;
    stats.relative_residual = relative_residual(x_mine, b_mine);
    // CG meeting negative curvature (an indefinite tangent) or stopping short: the caller shifts.
    stats.success = reason > 0 && x.allFinite();
    return stats;
  }

  const char* name() const override {
    return name_of(gamg_ ? LinearSolverOptions::Kind::PetscGamg : LinearSolverOptions::Kind::PetscMumps).data();
  }
  int factorizations() const override { return factorizations_; }
  bool wants_rigid_body_modes() const override { return gamg_; }
  void set_rigid_body_motions(RigidBodyMotions motions, int block_size) override {
    motions_ = std::move(motions);
    if (block_size != block_size_) {
      block_size_ = block_size;
      A_.reset();  // the block size is set before preallocation: rebuild on the next factorize
      ksp_.reset();
    }
  }
  long negative_eigenvalues() const override { return negative_; }
  bool adds_ranks_parts() const override { return distributed(); }
  void set_row_owners(std::vector<int> owner) override {
    if (owner == owner_) return;
    owner_ = std::move(owner);
    A_.reset();  // PETSc's rows change: rebuild on the next factorize
    ksp_.reset();
  }

 private:
  /// True when K has the pattern analyze() was given last: its column starts, and its row indices
  /// (kept as they are on one process; on several ranks read back through the renumbering, where
  /// entry j of PETSc's row i is K's value_source_[j], in K's column old_of_new[i] and at row
  /// old_of_new[row_columns_[j]]).
  bool same_pattern(const SparseMatrix& K) const {
    const auto nonzeros = static_cast<std::size_t>(K.nonZeros());
    if (starts_.size() != static_cast<std::size_t>(K.outerSize() + 1) ||
        !std::equal(starts_.begin(), starts_.end(), K.outerIndexPtr()))
      return false;
    if (!distributed())
      return columns_.size() == nonzeros && std::equal(columns_.begin(), columns_.end(), K.innerIndexPtr());
    if (value_source_.size() != nonzeros || row_starts_.size() != static_cast<std::size_t>(rows_) + 1) return false;
    const int* rows_of_K = K.innerIndexPtr();
    for (PetscInt i = 0; i < rows_; ++i) {
      const Index column = order_.old_of_new[static_cast<std::size_t>(i)];
      const PetscInt first = starts_[static_cast<std::size_t>(column)], last = starts_[static_cast<std::size_t>(column) + 1];
      if (row_starts_[static_cast<std::size_t>(i) + 1] - row_starts_[static_cast<std::size_t>(i)] != last - first) return false;
      for (PetscInt j = row_starts_[static_cast<std::size_t>(i)]; j < row_starts_[static_cast<std::size_t>(i) + 1]; ++j) {
        const PetscInt k = value_source_[static_cast<std::size_t>(j)];
        if (rows_of_K[k] != order_.old_of_new[static_cast<std::size_t>(row_columns_[static_cast<std::size_t>(j)])])
          return false;
      }
    }
    return true;
  }

  /// |A x - b| / |b| with PETSc's matrix (the one factorized; the caller's K may be gone), from
  /// this rank's rows of x and b.
  double relative_residual(const VectorX& x_mine, const VectorX& b_mine) const {
    VectorX Ax = VectorX::Zero(local_rows_);
    VecHandle px, pAx;
    wrap(x_mine, px);
    wrap(Ax, pAx);
    check(MatMult(A_.get(), px.get(), pAx.get()), "MatMult");
    double squares[2] = {(Ax - b_mine).squaredNorm(), b_mine.squaredNorm()};
    if (distributed()) parallel::sum(squares, 2);
    const double nb = std::sqrt(squares[1]);
    return nb > 0 ? std::sqrt(squares[0]) / nb : std::sqrt(squares[0]);
  }

  /// The rigid-body modes of this rank's rows (local_rows_, in PETSc's order) from motions_.
  /// Collective on several ranks.
  void compute_rigid_body_modes() {
    std::vector<Index> unknowns(static_cast<std::size_t>(local_rows_));
    for (PetscInt i = 0; i < local_rows_; ++i)
      unknowns[static_cast<std::size_t>(i)] =
          distributed() ? static_cast<Index>(order_.old_of_new[static_cast<std::size_t>(first_row_ + i)]) : static_cast<Index>(i);
    modes_ = rigid_body_modes_of_rows(motions_, unknowns);
    modes_layout_ = layout_;
  }

  /// GAMG's smoothers are Chebyshev polynomials over [0.1, 1.1] times an estimate of each level's
  /// largest eigenvalue (PETSc's default). An estimate too low by more than the 10 % makes the
  /// preconditioner indefinite and CG stops (DIVERGED_INDEFINITE_PC): on the 146 k-tet compressed
  /// block on two ranks, 41 of 83 solves, which the Newton solver then shifted (41 Newton
  /// iterations instead of 26). 20 % headroom removed every such stop there (docs/mpi.md). Left
  /// alone when PETSC_OPTIONS sets it.
  static void use_safe_chebyshev_bounds() {
    const char* option = "-mg_levels_ksp_chebyshev_esteig";
    PetscBool given = PETSC_FALSE;
    check(PetscOptionsHasName(nullptr, nullptr, option, &given), "PetscOptionsHasName");
    if (!given) check(PetscOptionsSetValue(nullptr, option, "0,0.1,0,1.2"), "PetscOptionsSetValue");
  }

  /// Preallocates A_ (sized, typed, its block size set) for the union of the ranks' parts of K
  /// (row_starts_ and row_columns_ on each rank): the parts' patterns differ, and a row's holder
  /// learns the columns the other ranks add to it through PETSc's preallocator, which passes the
  /// entries of rows held elsewhere to their holders. The matrix is then filled with zeros on the
  /// union, so that its pattern is fixed (MAT_NEW_NONZERO_LOCATION_ERR). Collective.
  void preallocate_union_of_parts(PetscInt n, bool blocked) {
    MatHandle counter;
    check(MatCreate(communicator(), &*counter), "MatCreate");
    check(MatSetSizes(counter.get(), local_rows_, local_rows_, n, n), "MatSetSizes");
    check(MatSetType(counter.get(), MATPREALLOCATOR), "MatSetType(preallocator)");
    if (blocked) check(MatSetBlockSize(counter.get(), block_size_), "MatSetBlockSize");
    check(MatSetUp(counter.get()), "MatSetUp");
    std::vector<PetscScalar> zeros;
    for (PetscInt row = 0; row < rows_; ++row) {
      const auto begin = row_starts_[static_cast<std::size_t>(row)], end = row_starts_[static_cast<std::size_t>(row) + 1];
      if (begin == end) continue;
      zeros.assign(static_cast<std::size_t>(end - begin), 0.0);
      check(MatSetValues(counter.get(), 1, &row, end - begin, row_columns_.data() + begin, zeros.data(), INSERT_VALUES),
            "MatSetValues(preallocator)");
    }
    check(MatAssemblyBegin(counter.get(), MAT_FINAL_ASSEMBLY), "MatAssemblyBegin(preallocator)");
    check(MatAssemblyEnd(counter.get(), MAT_FINAL_ASSEMBLY), "MatAssemblyEnd(preallocator)");
    check(MatPreallocatorPreallocate(counter.get(), PETSC_TRUE, A_.get()), "MatPreallocatorPreallocate");
  }

  /// Logs (rank 0, once) how the ranks share the first distributed matrix: their rows, the
  /// nonzeros that couple a row of one rank to a column of another, which PETSc's products and
  /// MUMPS's fronts exchange (few when the rows follow the mesh partition), and whether each rank
  /// adds its part of the tangent. Collective; A_ preallocated.
  void report_layout(PetscInt n) {
    reported_layout_ = true;
    Mat diagonal_part = nullptr, off_diagonal_part = nullptr;  // columns this rank holds, and the others'
    const PetscInt* column_map = nullptr;
    check(MatMPIAIJGetSeqAIJ(A_.get(), &diagonal_part, &off_diagonal_part, &column_map), "MatMPIAIJGetSeqAIJ");
    MatInfo on_rank{}, off_rank{};
    check(MatGetInfo(diagonal_part, MAT_LOCAL, &on_rank), "MatGetInfo");
    check(MatGetInfo(off_diagonal_part, MAT_LOCAL, &off_rank), "MatGetInfo");
    double counts[2] = {off_rank.nz_used, on_rank.nz_used + off_rank.nz_used};  // off-rank nonzeros, all of its rows'
    parallel::sum(counts, 2);
    const double rows[2] = {parallel::max(static_cast<double>(local_rows_)),
                            -parallel::max(-static_cast<double>(local_rows_))};
    logger().info("linear solve on {} ranks ({}): {} to {} of {} rows each, rows {}; {:.1f} % of the nonzeros couple two ranks; {}",
                  parallel::size(), name(), rows[1], rows[0], n,
                  owner_.size() == static_cast<std::size_t>(n) ? "by the mesh partition" : "in contiguous ranges",
                  counts[1] > 0 ? 100 * counts[0] / counts[1] : 0.0,
                  adds_ranks_parts() ? "each rank adds its part of the tangent" : "the tangent summed on every rank");
  }

  /// The ranks share the matrix (a run on several MPI ranks, docs/mpi.md).
  static bool distributed() { return parallel::size() > 1; }
  static MPI_Comm communicator() { return distributed() ? PETSC_COMM_WORLD : PETSC_COMM_SELF; }

  /// This rank's rows (local_rows_, in PETSc's order) of a vector of all unknowns.
  VectorX local_part(const VectorX& full) const {
    if (!distributed()) return full;
    VectorX mine(local_rows_);
    for (PetscInt i = 0; i < local_rows_; ++i) mine(i) = full(order_.old_of_new[static_cast<std::size_t>(first_row_ + i)]);
    return mine;
  }

  /// The vector of all `n` unknowns on every rank from each rank's rows `mine`.
  VectorX whole(const VectorX& mine, Index n) const {
    if (!distributed()) return mine;
    VectorX full = VectorX::Zero(n);
    for (PetscInt i = 0; i < local_rows_; ++i) full(order_.old_of_new[static_cast<std::size_t>(first_row_ + i)]) = mine(i);
    parallel::sum(full.data(), static_cast<std::size_t>(n));
    return full;
  }

  /// A PETSc vector viewing this rank's rows `mine` (no copy; PETSc writes into it when it is a
  /// solution).
  void wrap(const VectorX& mine, VecHandle& out) const {
    out.reset();
    if (distributed())
      check(VecCreateMPIWithArray(communicator(), 1, local_rows_, rows_, mine.data(), &*out),
            "VecCreateMPIWithArray");
    else
      check(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, local_rows_, mine.data(), &*out), "VecCreateSeqWithArray");
  }

  bool gamg_;
  double tolerance_;
  int max_iterations_;
  int block_size_ = 1;
  RigidBodyMotions motions_;  ///< set before a factorization that needs new modes, cleared by it
  MatrixX modes_;             ///< the rigid-body modes of this rank's rows (local_rows_ x up to 6)
  int layout_ = 0;            ///< counts the analyses (each may give this rank other rows)
  int modes_layout_ = -1;     ///< the layout modes_ was computed for
  MatHandle A_;
  KspHandle ksp_;
  PetscInt rows_ = 0;              ///< K's rows (all ranks')
  PetscInt first_row_ = 0;         ///< this rank's rows of PETSc's matrix: [first_row_, first_row_ + local_rows_)
  PetscInt local_rows_ = 0;
  std::vector<PetscInt> starts_;   ///< the analyzed pattern's column starts
  std::vector<PetscInt> columns_;  ///< and row indices (compressed columns of the symmetric K); on one process only
  std::vector<int> owner_;         ///< the rank of each unknown (set_row_owners), or empty
  RowOrder order_;                 ///< on several ranks: PETSc's rows as K's unknowns, rank by rank
  std::vector<PetscInt> row_starts_;    ///< on several ranks: K renumbered (all rows, PETSc's numbers),
  std::vector<PetscInt> row_columns_;   ///< compressed rows with sorted columns,
  std::vector<PetscInt> value_source_;  ///< and where each value is in K's values
  int factorizations_ = 0;
  long negative_ = -1;
  bool reported_layout_ = false;
};

}  // namespace

std::unique_ptr<LinearSolver> make_petsc_linear_solver(const LinearSolverOptions& options) {
  return std::make_unique<PetscSolver>(options);
}

MatrixX rigid_body_modes_of_rows(const LinearSolver::RigidBodyMotions& motions, const std::vector<Index>& unknowns) {
  MatrixX modes = motions(unknowns);
  if (parallel::size() == 1) return fem::orthonormal_basis(std::move(modes));
  for (int round = 0; round < 2; ++round) {
    MatrixX gram = modes.transpose() * modes;
    parallel::sum(gram.data(), static_cast<std::size_t>(gram.size()));
    modes = modes * fem::orthonormalizing_transform(gram);
  }
  return modes;
}

}  // namespace sinew::solver
