#pragma once
/// @file dual.hpp
/// Forward-mode automatic differentiation with a fixed number N of independent variables:
/// Dual<N> carries a value and its gradient (Hessians: tape.hpp). Only the operations the
/// contact integrals need (+, -, *, /, sqrt). Used to differentiate the per-pair contact integral
/// exactly through the moving polygon vertices (docs/theory.md); no heap allocation.

#include <cmath>

#include <Eigen/Core>

namespace sinew::contact {

/// Value and gradient with respect to N variables.
template <int N>
struct Dual {
  using Gradient = Eigen::Matrix<double, N, 1>;
  double v = 0;
  Gradient d = Gradient::Zero();

  Dual() = default;
  Dual(double value) : v(value) {}  // NOLINT: constants convert implicitly
  Dual(double value, const Gradient& gradient) : v(value), d(gradient) {}
  /// The independent variable number i (0 <= i < N) with the given value.
  static Dual variable(double value, int i) {
    Dual x(value);
    x.d[i] = 1;
    return x;
  }

  friend Dual operator+(const Dual& a, const Dual& b) { return {a.v + b.v, a.d + b.d}; }
  friend Dual operator-(const Dual& a, const Dual& b) { return {a.v - b.v, a.d - b.d}; }
  friend Dual operator-(const Dual& a) { return {-a.v, -a.d}; }
  friend Dual operator*(const Dual& a, const Dual& b) { return {a.v * b.v, a.v * b.d + b.v * a.d}; }
  friend Dual operator*(double s, const Dual& a) { return {s * a.v, s * a.d}; }
  friend Dual operator*(const Dual& a, double s) { return {s * a.v, s * a.d}; }
  friend Dual operator/(const Dual& a, const Dual& b) {
    const double inv = 1.0 / b.v;
    return {a.v * inv, (a.d - (a.v * inv) * b.d) * inv};
  }
  friend Dual operator/(const Dual& a, double s) { return {a.v / s, a.d / s}; }
  friend Dual sqrt(const Dual& a) {
    const double r = std::sqrt(a.v);
    return {r, a.d * (0.5 / r)};
  }
  Dual& operator+=(const Dual& b) { return *this = *this + b; }
};

}  // namespace sinew::contact
