#include "sinew/solver/linear_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>
#include <unsupported/Eigen/IterativeSolvers>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "sinew/core/error.hpp"
#include "sinew/solver/petsc_linear_solver.hpp"
#include "sinew/solver/serial_openmp.hpp"
#include "sinew/solver/triangle_mirror.hpp"

namespace sinew::solver {
namespace {

double relative_residual(const SparseMatrix& K, const VectorX& x, const VectorX& b) {
  const double nb = b.norm();
  return nb > 0 ? (K * x - b).norm() / nb : (K * x).norm();
}

/// CHOLMOD's supernodal LL^T, its OpenMP regions on the calling thread (serial_openmp.hpp), of
/// K's lower triangle: it is mirrored onto the upper one and K handed over as upper-stored, which
/// CHOLMOD permutes with one transpose instead of two (triangle_mirror.hpp).
/// With options.lagged_iterations > 0, a new matrix is not factorized at once: CG preconditioned
/// by the last good factorization solves with it, and only when CG does not reach
/// options.lagged_tolerance within that many iterations (or meets negative curvature) is the
/// matrix factorized (docs/solver.md, "Lagged factorizations").
class CholmodSolver final : public LinearSolver {
 public:
  explicit CholmodSolver(const LinearSolverOptions& options)
      : lagged_iterations_(options.lagged_iterations), lagged_tolerance_(options.lagged_tolerance) {
    // An indefinite matrix is an expected event (the caller regularizes); keep CHOLMOD quiet.
    llt_.cholmod().print = 0;
    // And stop at the failing supernode: by default CHOLMOD assembles and factorizes that
    // supernode a second time, up to the failing column, to leave a valid partial factor, which
    // the caller never uses (docs/solver.md, "A failed factorization stops at once").
    llt_.cholmod().quick_return_if_not_posdef = 1;
  }
  void analyze(const SparseMatrix& K) override {
    if (lagged_iterations_ > 0 && factor_valid_) {
      pattern_pending_ = true;  // analyzing now would discard the factor that preconditions CG
      return;
    }
    analyze_now(K);
  }
  bool factorize(const SparseMatrix& K) override {
    K_ = K;  // owned: the caller's matrix may be a temporary (a regularized copy)
    if (lagged_iterations_ > 0 && factor_valid_ && factor_size_ == K_.rows() && required_ > 0) {
      lagged_ = true;
      return true;
    }
    return factorize_now();
  }
  LinearSolveStats solve(const VectorX& b, VectorX& x) override {
    if (!lagged_) return direct_solve(b, x);
    LinearSolveStats stats = lagged_cg(b, x);
    stats.lagged = stats.success;
    if (stats.success) return stats;
    const int cg_iterations = stats.iterations;
    if (!factorize_now()) {
      stats = LinearSolveStats{};
      stats.iterations = cg_iterations;
      return stats;  // indefinite: the caller shifts
    }
    stats = direct_solve(b, x);
    stats.iterations = cg_iterations;
    return stats;
  }
  const char* name() const override { return name_of(LinearSolverOptions::Kind::Cholmod).data(); }
  int factorizations() const override { return factorizations_; }
  void require_relative_residual(double eta) override { required_ = eta; }

 private:
  void analyze_now(const SparseMatrix& K) {
    mirror_stale_ = true;
    const SerialOpenMpScope one_thread;
    llt_.analyzePattern(K);
    check_memory("analyze", K);
    pattern_pending_ = false;
    factor_valid_ = false;
  }
  bool factorize_now() {
    lagged_ = false;
    if (pattern_pending_) analyze_now(K_);
    K_.makeCompressed();
    if (mirror_stale_ || !fits(mirror_, K_)) mirror_ = triangle_mirror(K_);  // !fits: analyze() skipped
    mirror_stale_ = false;
    mirror_lower_to_upper(mirror_, K_);
    const SerialOpenMpScope one_thread;
    llt_.factorize(K_);
    check_memory("factorize", K_);
    ++factorizations_;
    factor_valid_ = llt_.info() == Eigen::Success;
    factor_size_ = K_.rows();
    return factor_valid_;
  }
  LinearSolveStats direct_solve(const VectorX& b, VectorX& x) {
    LinearSolveStats stats;
    const SerialOpenMpScope one_thread;
    x = llt_.solve(b);
    stats.success = llt_.info() == Eigen::Success && x.allFinite();
    stats.relative_residual = relative_residual(K_, x, b);
    return stats;
  }
  /// Preconditioned CG on K_ x = b from x = 0 with the last factorization as preconditioner.
  /// success only when |K_ x - b| <= min(lagged_tolerance, required) |b| within lagged_iterations and every
  /// search direction had positive curvature (so x is a descent direction for b = -g).
  LinearSolveStats lagged_cg(const VectorX& b, VectorX& x) {
    LinearSolveStats stats;
    x = VectorX::Zero(b.size());
    const double norm_b = b.norm();
    if (norm_b == 0) {
      stats.success = true;
      return stats;
    }
    const SerialOpenMpScope one_thread;
    VectorX r = b;
    VectorX z = llt_.solve(r);
    VectorX p = z;
    VectorX Kp(b.size());
    double rz = r.dot(z);
    for (int k = 1; k <= lagged_iterations_; ++k) {
      stats.iterations = k;
      Kp.noalias() = K_ * p;
      const double curvature = p.dot(Kp);
      if (!(curvature > 0) || !std::isfinite(curvature)) return stats;
      const double alpha = rz / curvature;
      x.noalias() += alpha * p;
      r.noalias() -= alpha * Kp;
      const double norm_r = r.norm();
      if (norm_r <= std::min(lagged_tolerance_, required_) * norm_b) {
        stats.relative_residual = norm_r / norm_b;
        stats.success = x.allFinite();
        return stats;
      }
      z = llt_.solve(r);
      const double rz_next = r.dot(z);
      p = z + (rz_next / rz) * p;
      rz = rz_next;
    }
    return stats;
  }
  /// CHOLMOD reports a failed allocation in its status; Eigen folds it into "not positive
  /// definite", which would send Newton into shifting and halving forever.
  void check_memory(const char* phase, const SparseMatrix& K) {
    if (llt_.cholmod().status == CHOLMOD_OUT_OF_MEMORY) {
      llt_.cholmod().status = CHOLMOD_OK;
      throw OutOfMemoryError(fmt::format("out of memory: CHOLMOD could not {} the {} x {} stiffness matrix ({} nonzeros)",
                                         phase, K.rows(), K.cols(), K.nonZeros()));
    }
  }

  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Upper> llt_;
  SparseMatrix K_;  ///< the matrix last given to factorize (its lower triangle mirrored once factorized)
  TriangleMirror mirror_;      ///< the twins of the analyzed pattern's entries
  bool mirror_stale_ = true;   ///< a new pattern was analyzed since mirror_ was built
  int lagged_iterations_ = 0;
  double lagged_tolerance_ = 1e-3;
  double required_ = 1;  ///< the caller's bound on the relative residual (require_relative_residual)
  int factorizations_ = 0;
  bool factor_valid_ = false;     ///< llt_ holds a good factorization (of some earlier matrix when lagged_)
  Index factor_size_ = 0;         ///< rows of the matrix factorized
  bool pattern_pending_ = false;  ///< K_'s pattern is new and not yet analyzed
  bool lagged_ = false;           ///< K_ is not factorized: solve with lagged CG
};

template <class Solver>
class IterativeSolver final : public LinearSolver {
 public:
  IterativeSolver(const LinearSolverOptions& options, const char* name) : name_(name) {
    solver_.setTolerance(options.tolerance);
    solver_.setMaxIterations(options.max_iterations);
    if constexpr (requires(Solver s) { s.set_restart(1); }) solver_.set_restart(options.gmres_restart);
  }
  void analyze(const SparseMatrix& K) override { solver_.analyzePattern(K); }
  bool factorize(const SparseMatrix& K) override {
    K_ = K;  // owned: Eigen's solver keeps a reference to the matrix, which may be a temporary
    solver_.factorize(K_);
    ++factorizations_;
    return solver_.info() != Eigen::NumericalIssue;
  }
  LinearSolveStats solve(const VectorX& b, VectorX& x) override {
    LinearSolveStats stats;
    x = solver_.solve(b);
    stats.iterations = static_cast<int>(solver_.iterations());
    stats.relative_residual = relative_residual(K_, x, b);
    // Reaching the iteration cap is normal for the seed's loose GMRES: the result is used if it
    // reduced the residual at all.
    stats.success = x.allFinite() && stats.relative_residual < 1.0;
    return stats;
  }
  const char* name() const override { return name_; }
  int factorizations() const override { return factorizations_; }

 private:
  Solver solver_;
  int factorizations_ = 0;
  SparseMatrix K_;  ///< the matrix last factorized (the solver refers to it)
  const char* name_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverOptions& options) {
  using Kind = LinearSolverOptions::Kind;
  switch (options.kind) {
    case Kind::Cholmod:
      return std::make_unique<CholmodSolver>(options);
    case Kind::Gmres:
      return std::make_unique<IterativeSolver<Eigen::GMRES<SparseMatrix, Eigen::DiagonalPreconditioner<double>>>>(
          options, name_of(Kind::Gmres).data());
    case Kind::ConjugateGradient:
      return std::make_unique<IterativeSolver<
          Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, Eigen::DiagonalPreconditioner<double>>>>(
          options, name_of(Kind::ConjugateGradient).data());
    case Kind::PetscGamg:
    case Kind::PetscMumps:
      return make_petsc_linear_solver(options);
  }
  return nullptr;
}

}  // namespace sinew::solver
