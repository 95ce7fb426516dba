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

namespace {

/// Three keyframes: rest at 0, 10 along x turned 90 degrees about z at 0.5, then 10 along x and
/// up 4 turned 170 degrees about z at 1; rotations about the pivot (1, 0, 0).
fem::RigidMotion keyframed() {
  fem::RigidMotion m;
  m.pivot = Vector3(1, 0, 0);
  auto key = [](double lambda, Vector3 t, double degrees) {
    fem::Keyframe k;
    k.lambda = lambda;
    k.translation = t;
    k.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(degrees * M_PI / 180, Vector3::UnitZ()));
    return k;
  };
  m.keyframes = {key(0, Vector3::Zero(), 0), key(0.5, Vector3(10, 0, 0), 90), key(1, Vector3(10, 0, 4), 170)};
  return m;
}

}  // namespace

TEST(Keyframes, ExactAtTheKeysAndHeldOutsideThem) {
  const fem::RigidMotion m = keyframed();
  const Vector3 X(2, 0, 0);  // 1 from the pivot along x
  EXPECT_NEAR((m.apply(X, 0.0) - X).norm(), 0, 1e-14);
  EXPECT_NEAR((m.apply(X, 0.5) - Vector3(11, 1, 0)).norm(), 0, 1e-14);
  const double a = 170 * M_PI / 180;
  EXPECT_NEAR((m.apply(X, 1.0) - Vector3(11 + std::cos(a), std::sin(a), 4)).norm(), 0, 1e-14);
  EXPECT_NEAR((m.apply(X, -0.5) - m.apply(X, 0.0)).norm(), 0, 0);
  EXPECT_NEAR((m.apply(X, 1.5) - m.apply(X, 1.0)).norm(), 0, 0);
  EXPECT_NEAR((m.apply(m.pivot, 0.5) - (m.pivot + Vector3(10, 0, 0))).norm(), 0, 1e-14);
  EXPECT_FALSE(m.is_identity());
}

TEST(Keyframes, TranslationIsLinearAndRotationIsSlerpAboutTheFixedAxis) {
  const fem::RigidMotion m = keyframed();
  for (double s : {0.1, 0.25, 0.6, 0.9}) {
    const double lambda = 0.5 * s;
    // Slerp between 0 and 90 degrees about z: the angle grows linearly, the axis stays z.
    const Eigen::AngleAxisd turn(m.rotation(lambda));
    EXPECT_NEAR(turn.angle(), s * M_PI / 2, 1e-12);
    EXPECT_NEAR((turn.axis() - Vector3::UnitZ()).norm(), 0, 1e-12);
    EXPECT_NEAR((m.offset(lambda) - (m.pivot - m.rotation(lambda) * m.pivot + Vector3(10 * s, 0, 0))).norm(), 0,
                1e-12);
  }
  // Second segment: from 90 to 170 degrees, 4 up.
  const Eigen::AngleAxisd turn(m.rotation(0.75));
  EXPECT_NEAR(turn.angle(), (90 + 40) * M_PI / 180, 1e-12);
  EXPECT_NEAR(m.apply(m.pivot, 0.75).z(), 2, 1e-12);
}

TEST(Keyframes, ThePoseIsContinuousAcrossEveryKey) {
  const fem::RigidMotion m = keyframed();
  const Vector3 X(3, -1, 2);
  for (double key : {0.0, 0.5, 1.0}) {
    for (double h : {1e-6, 1e-9}) {
      EXPECT_NEAR((m.apply(X, key - h) - m.apply(X, key)).norm(), 0, 1e3 * h);
      EXPECT_NEAR((m.apply(X, key + h) - m.apply(X, key)).norm(), 0, 1e3 * h);
    }
  }
}

TEST(Keyframes, LargestTurnIsTheAngleTheSlerpPathSweeps) {
  const fem::RigidMotion m = keyframed();
  EXPECT_NEAR(m.largest_turn(0, 0.5), M_PI / 2, 1e-12);
  EXPECT_NEAR(m.largest_turn(0.25, 0.75), M_PI / 4 + 40 * M_PI / 180, 1e-12);
  EXPECT_NEAR(m.largest_turn(0, 1), 170 * M_PI / 180, 1e-12);
  EXPECT_NEAR(m.largest_turn(1, 2), 0, 1e-15);
  fem::RigidMotion still;
  still.keyframes = {fem::Keyframe{}, fem::Keyframe{1.0, Vector3::Zero(), Eigen::Quaterniond::Identity()}};
  EXPECT_TRUE(still.is_identity());
}
