#pragma once
/// @file fd_check.hpp
/// Central finite differences for derivative tests (GUIDE.md section 3).

#include <algorithm>
#include <functional>

#include <Eigen/Core>

namespace sinew::testing {

/// Gradient of f at x by central differences with step h (same units as x). #x.
inline Eigen::VectorXd fd_gradient(const std::function<double(const Eigen::VectorXd&)>& f,
                                   const Eigen::VectorXd& x, double h) {
  Eigen::VectorXd g(x.size());
  Eigen::VectorXd xp = x;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    xp[i] = x[i] + h;
    const double fp = f(xp);
    xp[i] = x[i] - h;
    const double fm = f(xp);
    xp[i] = x[i];
    g[i] = (fp - fm) / (2 * h);
  }
  return g;
}

/// Jacobian of a vector function at x by central differences: #f(x) x #x.
inline Eigen::MatrixXd fd_jacobian(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& f,
                                   const Eigen::VectorXd& x, double h) {
  Eigen::VectorXd xp = x;
  Eigen::MatrixXd J;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    xp[i] = x[i] + h;
    const Eigen::VectorXd fp = f(xp);
    xp[i] = x[i] - h;
    const Eigen::VectorXd fm = f(xp);
    xp[i] = x[i];
    if (i == 0) J.resize(fp.size(), x.size());
    J.col(i) = (fp - fm) / (2 * h);
  }
  return J;
}

/// ||a - b|| / max(||a||, ||b||, floor): the error measure the derivative tests assert on.
inline double relative_error(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double floor = 1e-12) {
  return (a - b).norm() / std::max({a.norm(), b.norm(), floor});
}

}  // namespace sinew::testing
