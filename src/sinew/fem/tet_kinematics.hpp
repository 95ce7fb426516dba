#pragma once
/// @file tet_kinematics.hpp
/// Linear tetrahedron kinematics, total Lagrangian: F = Ds Dm^-1, and the linear map from
/// the 12 nodal coordinates to vec(F).

#include <vector>

#include "sinew/core/types.hpp"

namespace sinew::fem {

/// Rest data of one tet: Dm^-1 (3x3, inverse length) and rest volume V0 = |det Dm| / 6.
struct TetRestShape {
  Matrix3 Dm_inv;
  double volume = 0;
};

/// Dm = [X1-X0, X2-X0, X3-X0] for every tet; throws InputError for a degenerate tet.
std::vector<TetRestShape> compute_rest_shapes(const Positions& rest, const Tets& tets);

/// The 12 nodal coordinates of tet t, node-major: [x0; x1; x2; x3].
Vector12 gather_tet(const Positions& x, const Tets& tets, Index t);

/// F = Ds Dm^-1 with Ds = [x1-x0, x2-x0, x3-x0].
Matrix3 deformation_gradient(const Vector12& xe, const Matrix3& Dm_inv);

/// dvec(F)/dxe: 9 x 12 (vec column-major; xe node-major). Constant per tet.
Eigen::Matrix<double, 9, 12> deformation_gradient_jacobian(const Matrix3& Dm_inv);

}  // namespace sinew::fem
