#include "sinew/fem/rigid_body_modes.hpp"

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

namespace sinew::fem {

MatrixX rigid_body_motions(const DofMap& dofs, const State& state, const std::vector<Index>& unknowns) {
  const Index n = dofs.num_dofs();
  MatrixX motions = MatrixX::Zero(static_cast<Index>(unknowns.size()), 6);
  if (unknowns.empty()) return motions;
  std::vector<Index> row(static_cast<std::size_t>(n), -1);  // the output row of each unknown
  for (std::size_t i = 0; i < unknowns.size(); ++i) {
    const Index q = unknowns[i];
    if (q < 0 || q >= n) throw std::out_of_range("rigid_body_motions: unknown out of range");  // a programming error
    row[static_cast<std::size_t>(q)] = static_cast<Index>(i);
  }
  const auto wanted = [&](Index first, int count) {
    for (int k = 0; k < count; ++k)
      if (row[static_cast<std::size_t>(first + k)] >= 0) return true;
    return false;
  };
  const auto put = [&](Index first, const MatrixX& rows) {
    for (Index k = 0; k < rows.rows(); ++k)
      if (const Index r = row[static_cast<std::size_t>(first + k)]; r >= 0) motions.row(r) = rows.row(k);
  };
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
    if (!wanted(first, nd)) continue;
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
      put(first, J.transpose() * U);
    }
  }
  for (const auto& [first, fit] : shared) put(first, fit.JtJ.completeOrthogonalDecomposition().solve(fit.JtU));
  return motions;
}

MatrixX rigid_body_modes(const DofMap& dofs, const State& state) {
  const Index n = dofs.num_dofs();
  if (n == 0) return MatrixX::Zero(0, 6);
  std::vector<Index> every(static_cast<std::size_t>(n));
  std::iota(every.begin(), every.end(), Index{0});
  return orthonormal_basis(rigid_body_motions(dofs, state, every));
}

MatrixX orthonormal_basis(MatrixX columns) {
  // The QR overwrites `columns` and Q is built in its result, so that no more than two such
  // matrices are held at once.
  Eigen::ColPivHouseholderQR<Eigen::Ref<MatrixX>> qr(columns);
  qr.setThreshold(1e-10);
  const Index rank = qr.rank();
  MatrixX basis = MatrixX::Identity(columns.rows(), rank);
  qr.householderQ().applyThisOnTheLeft(basis);
  return basis;
}

MatrixX orthonormalizing_transform(const MatrixX& gram) {
  const Eigen::SelfAdjointEigenSolver<MatrixX> eigen(gram);
  if (eigen.info() != Eigen::Success || !gram.allFinite()) return MatrixX(gram.rows(), 0);  // no direction
  const VectorX& values = eigen.eigenvalues();  // ascending
  const double largest = values.size() > 0 ? values.maxCoeff() : 0.0;
  std::vector<Index> kept;
  for (Index i = values.size() - 1; i >= 0; --i)
    if (largest > 0 && values[i] > 1e-14 * largest) kept.push_back(i);
  MatrixX T(gram.rows(), static_cast<Index>(kept.size()));
  for (std::size_t c = 0; c < kept.size(); ++c)
    T.col(static_cast<Index>(c)) = eigen.eigenvectors().col(kept[c]) / std::sqrt(values[kept[c]]);
  return T;
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
