#pragma once
/// @file random_deformation.hpp
/// Reproducible random deformation gradients and rotations for the material tests.

#include <random>

#include "sinew/core/types.hpp"

namespace sinew::material::test_support {

/// A uniformly distributed random rotation (3x3, det +1).
inline Matrix3 random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  q.normalize();
  return q.toRotationMatrix();
}

/// A random F = R (I + H), |H_ij| <= 0.45, with det F in [min_det, max_det].
inline Matrix3 random_deformation(std::mt19937& rng, double min_det = 0.5, double max_det = 2.0) {
  std::uniform_real_distribution<double> uniform(-0.45, 0.45);
  for (;;) {
    Matrix3 H;
    for (int k = 0; k < 9; ++k) H.data()[k] = uniform(rng);
    const Matrix3 F = random_rotation(rng) * (Matrix3::Identity() + H);
    const double J = F.determinant();
    if (J >= min_det && J <= max_det) return F;
  }
}

}  // namespace sinew::material::test_support
