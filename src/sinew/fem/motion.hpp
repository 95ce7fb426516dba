#pragma once
/// @file motion.hpp
/// Prescribed motions as functions of the load parameter lambda in [0, 1] (statics) or of
/// time (dynamics): a piecewise-linear amplitude scales a final rigid motion.

#include <utility>
#include <vector>

#include "sinew/core/types.hpp"

namespace sinew::fem {

/// Piecewise-linear factor a(lambda) through (lambda, factor) points, sorted by lambda,
/// held constant outside them. Empty = the ramp a(lambda) = lambda.
struct Amplitude {
  std::vector<std::pair<double, double>> points;
  double operator()(double lambda) const;
};

/// x(lambda) = R(a * angle, axis) (X - axis_point) + axis_point + a * translation, a = amplitude(lambda).
struct RigidMotion {
  Vector3 translation = Vector3::Zero();  ///< final translation (length)
  Vector3 axis_point = Vector3::Zero();   ///< a point on the rotation axis (length)
  Vector3 axis = Vector3::UnitZ();        ///< rotation axis direction (normalized on use)
  double angle = 0;                       ///< final rotation angle, radians (right-hand rule)
  Amplitude amplitude;

  /// Rotation at lambda.
  Matrix3 rotation(double lambda) const;
  /// Translation part t at lambda such that x = R X + t.
  Vector3 offset(double lambda) const;
  /// Position at lambda of a point at rest position X.
  Vector3 apply(const Vector3& X, double lambda) const { return rotation(lambda) * X + offset(lambda); }
  bool is_identity() const { return translation.isZero(0) && angle == 0; }
  /// The largest angle (radians) by which the motion turns a body away from its pose at `from`
  /// anywhere in [from, to]: |angle| times the largest change of the amplitude there (the
  /// amplitude is piecewise linear, so its extremes are at `to` or at a point in between).
  double largest_turn(double from, double to) const;
};

}  // namespace sinew::fem
