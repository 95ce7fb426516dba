#include <gtest/gtest.h>

#include <cmath>

#include "sinew/fem/motion.hpp"
#include "sinew/fem/tet_kinematics.hpp"
#include "support/fd_check.hpp"

using namespace sinew;
namespace st = sinew::testing;

TEST(Amplitude, DefaultIsRampAndTableInterpolates) {
  fem::Amplitude ramp;
  EXPECT_DOUBLE_EQ(ramp(0.3), 0.3);
  fem::Amplitude table{{{0.0, 0.0}, {0.5, 1.0}, {1.0, 1.0}}};
  EXPECT_DOUBLE_EQ(table(0.25), 0.5);
  EXPECT_DOUBLE_EQ(table(0.75), 1.0);
  EXPECT_DOUBLE_EQ(table(2.0), 1.0);
  EXPECT_DOUBLE_EQ(table(-1.0), 0.0);
}

TEST(RigidMotion, RotationAboutOffsetAxis) {
  fem::RigidMotion m;
  m.axis_point = Vector3(1, 0, 0);
  m.axis = Vector3(0, 0, 2);
  m.angle = M_PI / 2;
  const Vector3 x = m.apply(Vector3(2, 0, 0), 1.0);
  EXPECT_NEAR((x - Vector3(1, 1, 0)).norm(), 0, 1e-14);
  EXPECT_NEAR((m.apply(Vector3(2, 0, 0), 0.5) - Vector3(1 + std::sqrt(0.5), std::sqrt(0.5), 0)).norm(), 0, 1e-14);
  EXPECT_NEAR((m.apply(m.axis_point, 0.7) - m.axis_point).norm(), 0, 1e-14);
}

TEST(TetKinematics, JacobianMatchesFiniteDifferences) {
  Positions X(4, 3);
  X << 0, 0, 0, 1, 0.1, 0, 0.2, 1, 0, 0.1, 0.3, 1.2;
  Tets T(1, 4);
  T << 0, 1, 2, 3;
  const auto rest = fem::compute_rest_shapes(X, T);
  EXPECT_NEAR(rest[0].volume, std::abs((X.row(1) - X.row(0)).cross(X.row(2) - X.row(0)).dot(X.row(3) - X.row(0))) / 6, 1e-15);
  const Vector12 xe = fem::gather_tet(X, T, 0);
  EXPECT_NEAR((fem::deformation_gradient(xe, rest[0].Dm_inv) - Matrix3::Identity()).norm(), 0, 1e-14);
  const Vector12 x = xe + 0.1 * Vector12::Random();
  const auto F = [&](const VectorX& v) -> VectorX {
    const Matrix3 f = fem::deformation_gradient(v, rest[0].Dm_inv);
    return Eigen::Map<const VectorX>(f.data(), 9);
  };
  const MatrixX fd = st::fd_jacobian(F, x, 1e-6);
  EXPECT_LT(st::relative_error(fem::deformation_gradient_jacobian(rest[0].Dm_inv), fd), 1e-9);
}
