#include "sinew/solver/linear_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>
#include <unsupported/Eigen/IterativeSolvers>

#include <fmt/format.h>

#include "sinew/core/error.hpp"

namespace sinew::solver {
namespace {

double relative_residual(const SparseMatrix& K, const VectorX& x, const VectorX& b) {
  const double nb = b.norm();
  return nb > 0 ? (K * x - b).norm() / nb : (K * x).norm();
}

class CholmodSolver final : public LinearSolver {
 public:
  CholmodSolver() {
    // An indefinite matrix is an expected event (the caller regularizes); keep CHOLMOD quiet.
    llt_.cholmod().print = 0;
  }
  void analyze(const SparseMatrix& K) override {
    llt_.analyzePattern(K);
    check_memory("analyze");
  }
  bool factorize(const SparseMatrix& K) override {
    K_ = K;  // owned: the caller's matrix may be a temporary (a regularized copy)
    llt_.factorize(K_);
    check_memory("factorize");
    return llt_.info() == Eigen::Success;
  }
  LinearSolveStats solve(const VectorX& b, VectorX& x) override {
    LinearSolveStats stats;
    x = llt_.solve(b);
    stats.success = llt_.info() == Eigen::Success && x.allFinite();
    stats.relative_residual = relative_residual(K_, x, b);
    return stats;
  }
  const char* name() const override { return name_of(LinearSolverOptions::Kind::Cholmod).data(); }

 private:
  /// CHOLMOD reports a failed allocation in its status; Eigen folds it into "not positive
  /// definite", which would send Newton into shifting and halving forever.
  void check_memory(const char* phase) {
    if (llt_.cholmod().status == CHOLMOD_OUT_OF_MEMORY) {
      llt_.cholmod().status = CHOLMOD_OK;
      throw OutOfMemoryError(fmt::format("out of memory: CHOLMOD could not {} the {} x {} stiffness matrix ({} nonzeros)",
                                         phase, K_.rows(), K_.cols(), K_.nonZeros()));
    }
  }

  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt_;
  SparseMatrix K_;  ///< the matrix last factorized
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

 private:
  Solver solver_;
  SparseMatrix K_;  ///< the matrix last factorized (the solver refers to it)
  const char* name_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverOptions& options) {
  using Kind = LinearSolverOptions::Kind;
  switch (options.kind) {
    case Kind::Cholmod:
      return std::make_unique<CholmodSolver>();
    case Kind::Gmres:
      return std::make_unique<IterativeSolver<Eigen::GMRES<SparseMatrix, Eigen::DiagonalPreconditioner<double>>>>(
          options, name_of(Kind::Gmres).data());
    case Kind::ConjugateGradient:
      return std::make_unique<IterativeSolver<
          Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, Eigen::DiagonalPreconditioner<double>>>>(
          options, name_of(Kind::ConjugateGradient).data());
  }
  return nullptr;
}

}  // namespace sinew::solver
