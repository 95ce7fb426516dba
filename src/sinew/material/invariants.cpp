/// @file invariants.cpp
/// Closed-form invariants of C = F^T F and their derivatives with respect to F.

#include "sinew/material/invariants.hpp"

namespace sinew::material {
namespace {

/// Skew matrix [v]x with [v]x w = v x w.
Matrix3 cross_matrix(const Vector3& v) {
  Matrix3 S;
  S << 0, -v.z(), v.y(),  //
      v.z(), 0, -v.x(),   //
      -v.y(), v.x(), 0;
  return S;
}

/// H += scale * d2J/dF2. cof col 0 = f1 x f2, col 1 = f2 x f0, col 2 = f0 x f1 (f_a the
/// columns of F), and d(u x v)/du = -[v]x, d(u x v)/dv = [u]x; diagonal blocks are zero.
void add_scaled_d2_J_dF2(const Matrix3& F, double scale, Matrix9& H) {
  const Matrix3 S0 = scale * cross_matrix(F.col(0));
  const Matrix3 S1 = scale * cross_matrix(F.col(1));
  const Matrix3 S2 = scale * cross_matrix(F.col(2));
  H.block<3, 3>(0, 3) -= S2;
  H.block<3, 3>(0, 6) += S1;
  H.block<3, 3>(3, 0) += S2;
  H.block<3, 3>(3, 6) -= S0;
  H.block<3, 3>(6, 0) -= S1;
  H.block<3, 3>(6, 3) += S0;
}

/// dI2/dF given C = F^T F and I1 = tr C.
Vector9 d_I2_dF_given(const Matrix3& F, const Matrix3& C, double I1) {
  return vec(2.0 * (I1 * F - F * C));
}

/// d2I2/dF2 given C = F^T F, B = F F^T, I1 = tr C. See the header for the formula; block
/// (j, l) (rows 3j.., columns 3l..) is
///   4 f_j f_l^T - 2 f_l f_j^T - 2 C(j, l) Id3 + delta_jl (2 I1 Id3 - 2 B),  f_j = column j of F.
Matrix9 d2_I2_dF2_given(const Matrix3& F, const Matrix3& C, const Matrix3& B, double I1) {
  Matrix9 H;
  const Matrix3 diagonal_extra = 2.0 * I1 * Matrix3::Identity() - 2.0 * B;
  for (int l = 0; l < 3; ++l) {
    for (int j = 0; j < 3; ++j) {
      Matrix3 block = 4.0 * F.col(j) * F.col(l).transpose() - 2.0 * F.col(l) * F.col(j).transpose();
      block.diagonal().array() -= 2.0 * C(j, l);
      if (j == l) block += diagonal_extra;
      H.block<3, 3>(3 * j, 3 * l) = block;
    }
  }
  return H;
}

}  // namespace

Invariants compute_invariants(const Matrix3& F) {
  const Matrix3 C = F.transpose() * F;
  Invariants inv;
  inv.I1 = C.trace();
  inv.I2 = 0.5 * (inv.I1 * inv.I1 - C.squaredNorm());  // tr C^2 = |C|^2 for symmetric C
  inv.J = F.determinant();
  return inv;
}

Matrix3 cofactor(const Matrix3& F) {
  Matrix3 cof;
  cof.col(0) = F.col(1).cross(F.col(2));
  cof.col(1) = F.col(2).cross(F.col(0));
  cof.col(2) = F.col(0).cross(F.col(1));
  return cof;
}

Vector9 d_I1_dF(const Matrix3& F) { return 2.0 * vec(F); }

Matrix9 d2_I1_dF2() { return 2.0 * Matrix9::Identity(); }

Vector9 d_I2_dF(const Matrix3& F) {
  const Matrix3 C = F.transpose() * F;
  return d_I2_dF_given(F, C, C.trace());
}

Matrix9 d2_I2_dF2(const Matrix3& F) {
  const Matrix3 C = F.transpose() * F;
  const Matrix3 B = F * F.transpose();
  return d2_I2_dF2_given(F, C, B, C.trace());
}

Vector9 d_J_dF(const Matrix3& F) { return vec(cofactor(F)); }

Matrix9 d2_J_dF2(const Matrix3& F) {
  Matrix9 H = Matrix9::Zero();
  add_scaled_d2_J_dF2(F, 1.0, H);
  return H;
}

Vector9 d_I3_dF(const Matrix3& F) { return 2.0 * F.determinant() * d_J_dF(F); }

Matrix9 d2_I3_dF2(const Matrix3& F) {
  const Vector9 gJ = d_J_dF(F);
  return 2.0 * gJ * gJ.transpose() + 2.0 * F.determinant() * d2_J_dF2(F);
}

void chain_rule_from_invariants(const Matrix3& F, const InvariantEnergy& energy, Matrix3* P,
                                Matrix9* dPdF) {
  if (P == nullptr && dPdF == nullptr) return;
  const Matrix3 C = F.transpose() * F;
  const double I1 = C.trace();
  const Matrix3 cof = cofactor(F);
  const Vector3& dpsi = energy.gradient;

  const bool has_I2 = dpsi[1] != 0.0 || energy.hessian.row(1).any();
  Vector9 g2 = Vector9::Zero();
  if (has_I2) g2 = d_I2_dF_given(F, C, I1);

  if (P != nullptr) {
    Matrix3 stress = (2.0 * dpsi[0]) * F + dpsi[2] * cof;
    if (has_I2) stress += dpsi[1] * unvec(g2);
    *P = stress;
  }
  if (dPdF == nullptr) return;

  Matrix9& H = *dPdF;
  if (dpsi[1] != 0.0) {
    H = dpsi[1] * d2_I2_dF2_given(F, C, F * F.transpose(), I1);
  } else {
    H.setZero();
  }
  H.diagonal().array() += 2.0 * dpsi[0];
  if (dpsi[2] != 0.0) add_scaled_d2_J_dF2(F, dpsi[2], H);

  // sum_kl psi_kl g_k g_l^T with g = (dI1/dF, dI2/dF, dJ/dF), as explicit outer products
  // (a 9x3 * 3x3 * 3x9 product would go through Eigen's general GEMM kernel, much slower).
  Eigen::Matrix<double, 9, 3> G;
  G.col(0) = 2.0 * vec(F);
  G.col(1) = g2;
  G.col(2) = vec(cof);
  for (int l = 0; l < 3; ++l) {
    for (int k = 0; k < 3; ++k) {
      const double coefficient = energy.hessian(k, l);
      if (coefficient != 0.0) H.noalias() += (coefficient * G.col(k)) * G.col(l).transpose();
    }
  }
}

}  // namespace sinew::material
