#pragma once
/// @file sparse_matrix.hpp
/// The scalar sparse matrix of the linear solvers (the q-space tangent K), compressed columns.

#include <Eigen/SparseCore>

namespace sinew {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

}  // namespace sinew
