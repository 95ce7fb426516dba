#include "sinew/fem/motion.hpp"

#include <algorithm>
#include <cmath>

namespace sinew::fem {

double Amplitude::operator()(double lambda) const {
  if (points.empty()) return lambda;
  if (lambda <= points.front().first) return points.front().second;
  if (lambda >= points.back().first) return points.back().second;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const auto& [l1, f1] = points[i];
    if (lambda <= l1) {
      const auto& [l0, f0] = points[i - 1];
      const double s = (lambda - l0) / (l1 - l0);
      return f0 + s * (f1 - f0);
    }
  }
  return points.back().second;
}

double RigidMotion::largest_turn(double from, double to) const {
  if (angle == 0) return 0;
  const double a0 = amplitude(from);
  double change = std::abs(amplitude(to) - a0);
  for (const auto& [lambda, factor] : amplitude.points)
    if (lambda > std::min(from, to) && lambda < std::max(from, to)) change = std::max(change, std::abs(factor - a0));
  return std::abs(angle) * change;
}

Matrix3 RigidMotion::rotation(double lambda) const {
  const double a = amplitude(lambda);
  if (angle == 0 || a == 0) return Matrix3::Identity();
  return Eigen::AngleAxisd(a * angle, axis.normalized()).toRotationMatrix();
}

Vector3 RigidMotion::offset(double lambda) const {
  const double a = amplitude(lambda);
  const Matrix3 R = rotation(lambda);
  return axis_point - R * axis_point + a * translation;
}

}  // namespace sinew::fem
