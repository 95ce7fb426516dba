/// @file psd_projection.cpp

#include "sinew/core/psd_projection.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <stdexcept>

namespace sinew {
namespace {

/// Symmetrize, keep a positive definite matrix as is, otherwise clamp negative eigenvalues.
template <class Matrix>
Matrix project_symmetric(const Matrix& A) {
  const Matrix symmetric = 0.5 * (A + A.transpose());
  const Eigen::LLT<Matrix> cholesky(symmetric);
  if (cholesky.info() == Eigen::Success) return symmetric;

  const Eigen::SelfAdjointEigenSolver<Matrix> eigen(symmetric);
  if (eigen.info() != Eigen::Success) return symmetric;  // only for NaN/inf input
  const auto& values = eigen.eigenvalues();
  if (values.minCoeff() >= 0.0) return symmetric;
  const auto& vectors = eigen.eigenvectors();
  return vectors * values.cwiseMax(0.0).asDiagonal() * vectors.transpose();
}

}  // namespace

Matrix9 project_to_psd(const Matrix9& A) { return project_symmetric(A); }

Matrix12 project_to_psd(const Matrix12& A) { return project_symmetric(A); }

Eigen::Matrix<double, 21, 21> project_to_psd(const Eigen::Matrix<double, 21, 21>& A) { return project_symmetric(A); }

void project_to_psd_in_place(Eigen::Ref<MatrixX> A) {
  // Programming error, not input: callers pass element or pair Hessians, square by construction.
  if (A.rows() != A.cols()) throw std::invalid_argument("project_to_psd_in_place: matrix is not square");
  if (A.size() == 0) return;
  A = project_symmetric(MatrixX(A));
}

}  // namespace sinew
