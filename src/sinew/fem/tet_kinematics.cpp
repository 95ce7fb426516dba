#include "sinew/fem/tet_kinematics.hpp"

#include <cmath>
#include <fmt/format.h>

#include "sinew/core/error.hpp"

namespace sinew::fem {

std::vector<TetRestShape> compute_rest_shapes(const Positions& rest, const Tets& tets) {
  std::vector<TetRestShape> shapes(static_cast<std::size_t>(tets.rows()));
  for (Index t = 0; t < tets.rows(); ++t) {
    Matrix3 Dm;
    for (int k = 0; k < 3; ++k) Dm.col(k) = (rest.row(tets(t, k + 1)) - rest.row(tets(t, 0))).transpose();
    const double det = Dm.determinant();
    if (!(std::abs(det) > 0) || !std::isfinite(det))
      throw InputError(fmt::format("tet {} is degenerate (zero rest volume)", t));
    shapes[t].Dm_inv = Dm.inverse();
    shapes[t].volume = std::abs(det) / 6.0;
  }
  return shapes;
}

Vector12 gather_tet(const Positions& x, const Tets& tets, Index t) {
  Vector12 xe;
  for (int a = 0; a < 4; ++a) xe.segment<3>(3 * a) = x.row(tets(t, a)).transpose();
  return xe;
}

Matrix3 deformation_gradient(const Vector12& xe, const Matrix3& Dm_inv) {
  Matrix3 Ds;
  for (int k = 0; k < 3; ++k) Ds.col(k) = xe.segment<3>(3 * (k + 1)) - xe.segment<3>(0);
  return Ds * Dm_inv;
}

Eigen::Matrix<double, 9, 12> deformation_gradient_jacobian(const Matrix3& Dm_inv) {
  // F(i,j) = sum_k Ds(i,k) Dm_inv(k,j), Ds(i,k) = x_{k+1,i} - x_{0,i}.
  Eigen::Matrix<double, 9, 12> B = Eigen::Matrix<double, 9, 12>::Zero();
  for (int j = 0; j < 3; ++j) {
    for (int k = 0; k < 3; ++k) {
      const double w = Dm_inv(k, j);
      for (int i = 0; i < 3; ++i) {
        B(i + 3 * j, 3 * (k + 1) + i) += w;
        B(i + 3 * j, i) -= w;
      }
    }
  }
  return B;
}

}  // namespace sinew::fem
