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

namespace {

/// The keyframe segment of `lambda`: index i of the keyframe before it and the fraction s in
/// [0, 1] towards keyframe i + 1 (i is the last index with s = 0 after the last keyframe).
std::pair<std::size_t, double> keyframe_segment(const std::vector<Keyframe>& keys, double lambda) {
  if (lambda <= keys.front().lambda) return {0, 0.0};
  if (lambda >= keys.back().lambda) return {keys.size() - 1, 0.0};
  std::size_t i = 0;
  while (i + 2 < keys.size() && lambda >= keys[i + 1].lambda) ++i;
  return {i, (lambda - keys[i].lambda) / (keys[i + 1].lambda - keys[i].lambda)};
}

Eigen::Quaterniond keyframe_rotation(const std::vector<Keyframe>& keys, double lambda) {
  const auto [i, s] = keyframe_segment(keys, lambda);
  if (s == 0) return keys[i].rotation;
  return keys[i].rotation.slerp(s, keys[i + 1].rotation);
}

Vector3 keyframe_translation(const std::vector<Keyframe>& keys, double lambda) {
  const auto [i, s] = keyframe_segment(keys, lambda);
  if (s == 0) return keys[i].translation;
  return (1 - s) * keys[i].translation + s * keys[i + 1].translation;
}

}  // namespace

bool RigidMotion::is_identity() const {
  if (keyframes.empty()) return translation.isZero(0) && angle == 0;
  for (const Keyframe& key : keyframes)
    if (!key.translation.isZero(0) || key.rotation.angularDistance(Eigen::Quaterniond::Identity()) != 0) return false;
  return true;
}

double RigidMotion::largest_turn(double from, double to) const {
  if (!keyframes.empty()) {
    // The length of the slerp path between the two parameters bounds every turn along it.
    const double lo = std::min(from, to), hi = std::max(from, to);
    double swept = 0;
    for (std::size_t i = 0; i + 1 < keyframes.size(); ++i) {
      const double a = keyframes[i].lambda, b = keyframes[i + 1].lambda;
      const double overlap = std::min(hi, b) - std::max(lo, a);
      if (overlap <= 0) continue;
      swept += keyframes[i].rotation.angularDistance(keyframes[i + 1].rotation) * overlap / (b - a);
    }
    return swept;
  }
  if (angle == 0) return 0;
  const double a0 = amplitude(from);
  double change = std::abs(amplitude(to) - a0);
  for (const auto& [lambda, factor] : amplitude.points)
    if (lambda > std::min(from, to) && lambda < std::max(from, to)) change = std::max(change, std::abs(factor - a0));
  return std::abs(angle) * change;
}

Matrix3 RigidMotion::rotation(double lambda) const {
  if (!keyframes.empty()) return keyframe_rotation(keyframes, lambda).toRotationMatrix();
  const double a = amplitude(lambda);
  if (angle == 0 || a == 0) return Matrix3::Identity();
  return Eigen::AngleAxisd(a * angle, axis.normalized()).toRotationMatrix();
}

Vector3 RigidMotion::offset(double lambda) const {
  if (!keyframes.empty()) return pivot - rotation(lambda) * pivot + keyframe_translation(keyframes, lambda);
  const double a = amplitude(lambda);
  const Matrix3 R = rotation(lambda);
  return axis_point - R * axis_point + a * translation;
}

}  // namespace sinew::fem
