#pragma once
/// @file motion.hpp
/// Prescribed motions as functions of the load parameter lambda in [0, 1] (statics) or of
/// time (dynamics): a piecewise-linear amplitude scales a final rigid motion.

#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "sinew/core/types.hpp"

namespace sinew::fem {

/// Piecewise-linear factor a(lambda) through (lambda, factor) points, sorted by lambda,
/// held constant outside them. Empty = the ramp a(lambda) = lambda.
struct Amplitude {
  std::vector<std::pair<double, double>> points;
  double operator()(double lambda) const;
};

/// A pose of a keyframed motion at load parameter `lambda`: x = rotation (X - pivot) + pivot +
/// translation.
struct Keyframe {
  double lambda = 0;                                           ///< load parameter (time / end_time in dynamics)
  Vector3 translation = Vector3::Zero();                       ///< (length)
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  ///< unit quaternion
};

/// x(lambda) = R(a * angle, axis) (X - axis_point) + axis_point + a * translation, a = amplitude(lambda);
/// or, with keyframes, the keyframes' poses interpolated.
struct RigidMotion {
  Vector3 translation = Vector3::Zero();  ///< final translation (length)
  Vector3 axis_point = Vector3::Zero();   ///< a point on the rotation axis (length)
  Vector3 axis = Vector3::UnitZ();        ///< rotation axis direction (normalized on use)
  double angle = 0;                       ///< final rotation angle, radians (right-hand rule)
  Amplitude amplitude;
  /// When not empty (lambda strictly increasing), the motion instead of translation, angle and
  /// amplitude: between two keyframes the translation is interpolated linearly and the rotation
  /// by spherical linear interpolation (slerp: constant angular speed about a fixed axis);
  /// before the first keyframe and after the last the pose is held.
  std::vector<Keyframe> keyframes;
  Vector3 pivot = Vector3::Zero();  ///< keyframes: the point their rotations turn about (length)

  /// Rotation at lambda.
  Matrix3 rotation(double lambda) const;
  /// Translation part t at lambda such that x = R X + t.
  Vector3 offset(double lambda) const;
  /// Position at lambda of a point at rest position X.
  Vector3 apply(const Vector3& X, double lambda) const { return rotation(lambda) * X + offset(lambda); }
  bool is_identity() const;
  /// The largest angle (radians) by which the motion turns a body away from its pose at `from`
  /// anywhere in [from, to]: |angle| times the largest change of the amplitude there (the
  /// amplitude is piecewise linear, so its extremes are at `to` or at a point in between); with
  /// keyframes, the angle the slerp path sweeps between them (a bound of the largest turn).
  double largest_turn(double from, double to) const;
};

}  // namespace sinew::fem
