#pragma once
/// @file psd_projection.hpp
/// Projection of a symmetric matrix onto the positive semi-definite cone (docs/theory.md;
/// the modern answer to indefinite element Hessians, as in IPC/PolyFEM).
///
/// For A = Q diag(lambda) Q^T the projection is Q diag(max(lambda, 0)) Q^T, the nearest PSD
/// matrix in the Frobenius norm. The input is symmetrized first, (A + A^T) / 2. A matrix that
/// is already positive definite (detected by a Cholesky factorization, cheaper than the
/// eigen-decomposition) is returned unchanged.

#include <Eigen/Core>

#include "sinew/core/types.hpp"

namespace sinew {

/// PSD projection of a 9x9 matrix (e.g. a material tangent dP/dF). Heap-free.
Matrix9 project_to_psd(const Matrix9& A);

/// PSD projection of a 12x12 matrix (e.g. a linear tetrahedron's element Hessian). Heap-free.
Matrix12 project_to_psd(const Matrix12& A);

/// PSD projection of a 21x21 matrix (a contact pair: triangle and tet vertices). Heap-free.
Eigen::Matrix<double, 21, 21> project_to_psd(const Eigen::Matrix<double, 21, 21>& A);
/// PSD projection of a square matrix of any size, in place (allocates for the
/// eigen-decomposition). A must be square.
void project_to_psd_in_place(Eigen::Ref<MatrixX> A);

}  // namespace sinew
