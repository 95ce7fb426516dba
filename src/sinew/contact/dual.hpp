#pragma once
/// @file dual.hpp
/// Forward-mode automatic differentiation with a fixed number N of independent variables:
/// Dual<N> carries a value and its gradient, Dual2<N> also the Hessian. Only the operations the
/// contact integrals need (+, -, *, /, sqrt). Used to differentiate the per-pair contact integral
/// exactly through the moving polygon vertices (GUIDE.md section 1); no heap allocation.

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

/// Value, gradient and Hessian with respect to N variables.
template <int N>
struct Dual2 {
  using Gradient = Eigen::Matrix<double, N, 1>;
  using Hessian = Eigen::Matrix<double, N, N>;
  double v = 0;
  Gradient d = Gradient::Zero();
  Hessian h = Hessian::Zero();

  Dual2() = default;
  Dual2(double value) : v(value) {}  // NOLINT: constants convert implicitly
  Dual2(double value, const Gradient& gradient, const Hessian& hessian) : v(value), d(gradient), h(hessian) {}
  static Dual2 variable(double value, int i) {
    Dual2 x(value);
    x.d[i] = 1;
    return x;
  }

  friend Dual2 operator+(const Dual2& a, const Dual2& b) { return {a.v + b.v, a.d + b.d, a.h + b.h}; }
  friend Dual2 operator-(const Dual2& a, const Dual2& b) { return {a.v - b.v, a.d - b.d, a.h - b.h}; }
  friend Dual2 operator-(const Dual2& a) { return {-a.v, -a.d, -a.h}; }
  friend Dual2 operator*(const Dual2& a, const Dual2& b) {
    Dual2 r;
    r.v = a.v * b.v;
    r.d = a.v * b.d + b.v * a.d;
    r.h.noalias() = a.v * b.h + b.v * a.h;
    r.h.noalias() += a.d * b.d.transpose();
    r.h.noalias() += b.d * a.d.transpose();
    return r;
  }
  friend Dual2 operator*(double s, const Dual2& a) { return {s * a.v, s * a.d, s * a.h}; }
  friend Dual2 operator*(const Dual2& a, double s) { return {s * a.v, s * a.d, s * a.h}; }
  /// f(a) for a scalar function with derivatives f1 = f'(a.v), f2 = f''(a.v).
  static Dual2 chain(const Dual2& a, double f, double f1, double f2) {
    Dual2 r;
    r.v = f;
    r.d = f1 * a.d;
    r.h.noalias() = f1 * a.h;
    r.h.noalias() += f2 * a.d * a.d.transpose();
    return r;
  }
  friend Dual2 operator/(const Dual2& a, const Dual2& b) {
    const double inv = 1.0 / b.v;
    return a * chain(b, inv, -inv * inv, 2 * inv * inv * inv);
  }
  friend Dual2 operator/(const Dual2& a, double s) { return (1.0 / s) * a; }
  friend Dual2 sqrt(const Dual2& a) {
    const double r = std::sqrt(a.v);
    return chain(a, r, 0.5 / r, -0.25 / (r * r * r));
  }
  Dual2& operator+=(const Dual2& b) { return *this = *this + b; }
};

/// The plain value of any of double, Dual, Dual2.
inline double value_of(double x) { return x; }
template <int N>
double value_of(const Dual<N>& x) { return x.v; }
template <int N>
double value_of(const Dual2<N>& x) { return x.v; }

}  // namespace sinew::contact
