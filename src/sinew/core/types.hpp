#pragma once
/// @file types.hpp
/// Plain Eigen aliases shared by every module. Shapes are stated where they are used;
/// positions are always #V x 3 row-major-by-node matrices (one node per row).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>

namespace sinew {

using Index = std::int32_t;  ///< node, element and degree-of-freedom indices

using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;
using Matrix9 = Eigen::Matrix<double, 9, 9>;
using Vector9 = Eigen::Matrix<double, 9, 1>;
using Vector12 = Eigen::Matrix<double, 12, 1>;
using Matrix12 = Eigen::Matrix<double, 12, 12>;
using VectorX = Eigen::VectorXd;
using MatrixX = Eigen::MatrixXd;

/// Node positions, #V x 3 (one node per row), in the scene's length unit.
using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// Tetrahedra, #T x 4 node indices. Positive orientation: det[x1-x0, x2-x0, x3-x0] > 0.
using Tets = Eigen::Matrix<Index, Eigen::Dynamic, 4, Eigen::RowMajor>;
/// Triangles, #F x 3 node indices, counter-clockwise seen from outside.
using Triangles = Eigen::Matrix<Index, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// One integer per element or node (region ids, flags).
using IndexVector = Eigen::Matrix<Index, Eigen::Dynamic, 1>;

}  // namespace sinew
