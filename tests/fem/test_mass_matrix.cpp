#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "sinew/core/error.hpp"
#include "sinew/fem/external_force_energy.hpp"
#include "sinew/fem/mass_matrix.hpp"
#include "support/box_mesh.hpp"
#include "support/flat_positions.hpp"

using namespace sinew;
namespace st = sinew::testing;
using st::flatten;
using fem::MassKind;

namespace {

/// A 2 x 2 x 1 box [0,2]x[0,1]x[0,0.5] (24 tets) with a second region (x > 1) of another density,
/// the rest positions jiggled so that the tets differ in volume.
mesh::TetMesh two_region_box() {
  auto m = st::box_mesh(2, 2, 1, Vector3(0, 0, 0), Vector3(2, 1, 0.5));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (Index a = 0; a < m.num_nodes(); ++a)
    for (int k = 0; k < 3; ++k) m.rest(a, k) += u(rng);
  for (Index t = 0; t < m.num_tets(); ++t) {
    Vector3 c = Vector3::Zero();
    for (int i = 0; i < 4; ++i) c += m.rest.row(m.tets(t, i)).transpose() / 4.0;
    m.region[t] = c.x() > 1.0 ? 1 : 0;
  }
  m.region_names = {"left", "right"};
  return m;
}

const std::vector<double> kDensity{2.0, 0.5};

double total_mass(const mesh::TetMesh& m, const std::vector<double>& density) {
  double sum = 0;
  for (Index t = 0; t < m.num_tets(); ++t)
    sum += density[static_cast<std::size_t>(m.region[t])] * std::abs(mesh::signed_volume(m.rest, m.tets, t));
  return sum;
}

/// The full 3#V x 3#V matrix M (x) I3, node-major degrees of freedom 3 a + k.
MatrixX expand3(const Eigen::SparseMatrix<double>& M) {
  const MatrixX D = MatrixX(M);
  MatrixX full = MatrixX::Zero(3 * D.rows(), 3 * D.cols());
  for (Index a = 0; a < D.rows(); ++a)
    for (Index b = 0; b < D.cols(); ++b) full.block<3, 3>(3 * a, 3 * b) = D(a, b) * Matrix3::Identity();
  return full;
}

}  // namespace

class MassMatrixKinds : public ::testing::TestWithParam<MassKind> {};

TEST_P(MassMatrixKinds, TotalMassIsDensityTimesVolumeInEachDirection) {
  const auto m = two_region_box();
  const MatrixX M3 = expand3(fem::mass_matrix(m.rest, m.tets, m.region, kDensity, GetParam()));
  const double mass = total_mass(m, kDensity);
  ASSERT_GT(mass, 0);
  for (int d = 0; d < 3; ++d) {
    VectorX ud = VectorX::Zero(M3.rows());
    for (Index a = 0; a < m.num_nodes(); ++a) ud[3 * a + d] = 1;
    EXPECT_NEAR(ud.dot(M3 * ud), mass, 1e-12 * mass) << "direction " << d;
    // the x rows carry no y or z mass
    for (int e = 0; e < 3; ++e) {
      if (e == d) continue;
      VectorX ue = VectorX::Zero(M3.rows());
      for (Index a = 0; a < m.num_nodes(); ++a) ue[3 * a + e] = 1;
      EXPECT_EQ(ud.dot(M3 * ue), 0.0);
    }
  }
}

TEST_P(MassMatrixKinds, RigidTranslationKineticEnergyIsHalfMassSpeedSquared) {
  const auto m = two_region_box();
  const MatrixX M3 = expand3(fem::mass_matrix(m.rest, m.tets, m.region, kDensity, GetParam()));
  const Vector3 v(0.3, -1.2, 2.5);
  const Positions velocity = Positions::Ones(m.num_nodes(), 3) * v.asDiagonal();
  const VectorX vf = flatten(velocity);
  const double mass = total_mass(m, kDensity);
  EXPECT_NEAR(0.5 * vf.dot(M3 * vf), 0.5 * mass * v.squaredNorm(), 1e-12 * mass * v.squaredNorm());
}

TEST_P(MassMatrixKinds, InvertedRestTetWeighsLikeItsMirrorAndDegenerateTetThrows) {
  auto m = two_region_box();
  const Eigen::SparseMatrix<double> M = fem::mass_matrix(m.rest, m.tets, m.region, kDensity, GetParam());
  Tets flipped = m.tets;
  std::swap(flipped(5, 1), flipped(5, 2));  // negative orientation, same element
  ASSERT_LT(mesh::signed_volume(m.rest, flipped, 5), 0);
  const Eigen::SparseMatrix<double> Mf = fem::mass_matrix(m.rest, flipped, m.region, kDensity, GetParam());
  EXPECT_LT((MatrixX(M) - MatrixX(Mf)).norm(), 1e-15 * MatrixX(M).norm());

  Positions flat_rest = m.rest;
  for (int i = 1; i < 4; ++i) flat_rest.row(m.tets(3, i)) = m.rest.row(m.tets(3, 0));  // zero volume
  EXPECT_THROW(fem::mass_matrix(flat_rest, m.tets, m.region, kDensity, GetParam()), InputError);
}

TEST_P(MassMatrixKinds, NegativeOrNonFiniteDensityIsAnInputError) {
  const auto m = two_region_box();
  try {
    fem::mass_matrix(m.rest, m.tets, m.region, {2.0, -0.5}, GetParam());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("density of region 1 must be finite and >= 0, got -0.5"));
  }
  EXPECT_THROW(fem::mass_matrix(m.rest, m.tets, m.region, {std::nan(""), 1.0}, GetParam()), InputError);
  // zero density is allowed (massless regions), it just contributes nothing
  const auto M = fem::mass_matrix(m.rest, m.tets, m.region, {0.0, 0.5}, GetParam());
  EXPECT_NEAR(M.sum(), total_mass(m, {0.0, 0.5}), 1e-14);
  // a region id without a density is a programming error
  IndexVector bad = m.region;
  bad[0] = 2;
  EXPECT_THROW(fem::mass_matrix(m.rest, m.tets, bad, kDensity, GetParam()), Error);
}

TEST_P(MassMatrixKinds, NodesInNoTetHaveAStoredZeroDiagonal) {
  auto m = two_region_box();
  Positions rest(m.num_nodes() + 1, 3);
  rest.topRows(m.num_nodes()) = m.rest;
  rest.row(m.num_nodes()) = Eigen::RowVector3d(5, 5, 5);  // an orphan node
  const Eigen::SparseMatrix<double> M = fem::mass_matrix(rest, m.tets, m.region, kDensity, GetParam());
  ASSERT_EQ(M.rows(), m.num_nodes() + 1);
  for (Index a = 0; a < M.rows(); ++a) {
    bool stored = false;
    for (Eigen::SparseMatrix<double>::InnerIterator it(M, a); it; ++it) stored |= it.row() == a;
    EXPECT_TRUE(stored) << "node " << a;
  }
  EXPECT_EQ(M.coeff(m.num_nodes(), m.num_nodes()), 0.0);
  EXPECT_EQ(M.col(m.num_nodes()).sum(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Kinds, MassMatrixKinds, ::testing::Values(MassKind::Lumped, MassKind::Consistent),
                         [](const auto& info) { return info.param == MassKind::Lumped ? "Lumped" : "Consistent"; });

TEST(MassMatrix, SingleTetEntries) {
  Positions X(4, 3);
  X << 0, 0, 0, 2, 0, 0, 0, 3, 0, 0, 0, 1;  // V0 = 1
  Tets T(1, 4);
  T << 0, 1, 2, 3;
  const IndexVector region = IndexVector::Zero(1);
  const MatrixX C = MatrixX(fem::mass_matrix(X, T, region, {20.0}, MassKind::Consistent));
  const MatrixX expected = MatrixX::Ones(4, 4) + MatrixX::Identity(4, 4);  // rho V0 / 20 (1 + delta)
  EXPECT_LT((C - expected).norm(), 1e-14);
  const MatrixX L = MatrixX(fem::mass_matrix(X, T, region, {20.0}, MassKind::Lumped));
  EXPECT_LT((L - 5.0 * MatrixX::Identity(4, 4)).norm(), 1e-14);
}

TEST(MassMatrix, ConsistentIsSymmetricPositiveDefiniteWithLumpedRowSums) {
  const auto m = two_region_box();
  const MatrixX C = MatrixX(fem::mass_matrix(m.rest, m.tets, m.region, kDensity, MassKind::Consistent));
  const MatrixX L = MatrixX(fem::mass_matrix(m.rest, m.tets, m.region, kDensity, MassKind::Lumped));
  EXPECT_EQ((C - C.transpose()).norm(), 0.0);
  const Eigen::SelfAdjointEigenSolver<MatrixX> eig(C);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
  EXPECT_EQ(Eigen::LLT<MatrixX>(C).info(), Eigen::Success);

  // row sums of the consistent matrix are the lumped diagonal; the lumped matrix is diagonal
  const VectorX row_sums = C.rowwise().sum();
  EXPECT_LT((row_sums - L.diagonal()).norm(), 1e-14 * L.diagonal().norm());
  EXPECT_EQ((L - MatrixX(L.diagonal().asDiagonal())).norm(), 0.0);
  // and the lumped diagonal is what gravity uses
  const VectorX lumped = fem::lumped_masses(m.rest, m.tets, m.region, kDensity);
  EXPECT_LT((lumped - L.diagonal()).norm(), 1e-15 * lumped.norm());
}

TEST(MassMatrix, ConsistentIntegratesRigidRotationKineticEnergyExactly) {
  // P1 interpolates linear velocity fields exactly, so 0.5 v^T C v = 0.5 w . I w with I the
  // inertia tensor of the uniform box about its center; the lumped mass only approximates it.
  const Vector3 lo(-1, -0.5, -0.25), hi(1, 0.5, 0.25);
  const auto m = st::box_mesh(4, 2, 2, lo, hi);
  const double rho = 3.0;
  const Vector3 e = hi - lo;
  const double mass = rho * e.prod();
  const Vector3 inertia(mass / 12 * (e.y() * e.y() + e.z() * e.z()), mass / 12 * (e.x() * e.x() + e.z() * e.z()),
                        mass / 12 * (e.x() * e.x() + e.y() * e.y()));
  const Vector3 w(0.4, -1.0, 0.7);
  const double exact = 0.5 * w.dot(inertia.asDiagonal() * w);

  Positions velocity(m.num_nodes(), 3);
  for (Index a = 0; a < m.num_nodes(); ++a) velocity.row(a) = w.cross(Vector3(m.rest.row(a))).transpose();
  const VectorX v = flatten(velocity);
  const MatrixX C3 = expand3(fem::mass_matrix(m.rest, m.tets, m.region, {rho}, MassKind::Consistent));
  const MatrixX L3 = expand3(fem::mass_matrix(m.rest, m.tets, m.region, {rho}, MassKind::Lumped));
  EXPECT_NEAR(0.5 * v.dot(C3 * v), exact, 1e-12 * exact);
  EXPECT_GT(std::abs(0.5 * v.dot(L3 * v) - exact), 1e-3 * exact);  // lumping is an approximation
}
