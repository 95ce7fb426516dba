#include "sinew/fem/rigid_body_modes.hpp"

#include <unordered_map>

#include <Eigen/QR>

namespace sinew::fem {

MatrixX rigid_body_modes(const DofMap& dofs, const State& state) {
  const Index n = dofs.num_dofs();
  MatrixX modes = MatrixX::Zero(n, 6);
  if (n == 0) return modes;
  const Vector3 centroid = state.x.colwise().mean().transpose();
  // Normal equations of the fit per group of unknowns that nodes share (a free rigid body's six).
  struct Fit {
    MatrixX JtJ;
    MatrixX JtU;
  };
  std::unordered_map<Index, Fit> shared;
  for (Index a = 0; a < state.x.rows(); ++a) {
    const int nd = dofs.num_node_dofs(a);
    if (nd == 0) continue;
    const Index first = dofs.first_dof(a);
    Eigen::Matrix<double, 3, 6> U;  // displacement of node a under each unit mode
    U.leftCols<3>().setIdentity();
    const Vector3 arm = state.x.row(a).transpose() - centroid;
    for (int k = 0; k < 3; ++k) U.col(3 + k) = Vector3::Unit(k).cross(arm);
    const auto J = dofs.node_jacobian(state, a);
    if (dofs.kind(a) == DofMap::NodeKind::RigidMember) {
      Fit& fit = shared[first];
      if (fit.JtJ.size() == 0) {
        fit.JtJ = MatrixX::Zero(nd, nd);
        fit.JtU = MatrixX::Zero(nd, 6);
      }
      fit.JtJ += J.transpose() * J;
      fit.JtU += J.transpose() * U;
    } else {
      // Free and planar nodes: J has orthonormal columns, so the fit is J^T U.
      modes.middleRows(first, nd) = J.transpose() * U;
    }
  }
  for (const auto& [first, fit] : shared)
    modes.middleRows(first, fit.JtJ.rows()) = fit.JtJ.completeOrthogonalDecomposition().solve(fit.JtU);
  // Orthonormal basis of the columns' span, dropping what the constraints removed.
  Eigen::ColPivHouseholderQR<MatrixX> qr(modes);
  qr.setThreshold(1e-10);
  const Index rank = qr.rank();
  return qr.householderQ() * MatrixX::Identity(n, rank);
}

int unknowns_block_size(const DofMap& dofs, Index num_nodes) {
  if (dofs.num_dofs() % 3 != 0) return 1;
  for (Index a = 0; a < num_nodes; ++a) {
    const int nd = dofs.num_node_dofs(a);
    if (nd != 0 && (nd % 3 != 0 || dofs.first_dof(a) % 3 != 0)) return 1;
  }
  return 3;
}

}  // namespace sinew::fem
