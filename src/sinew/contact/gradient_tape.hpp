#pragma once
/// @file gradient_tape.hpp
/// Exact gradients by plain reverse mode: ReverseScalar records each operation of a scalar
/// computation on the calling thread's active GradientTape (value, at most two operands and the
/// local partial derivatives as doubles); one backward sweep of scalar adjoints gives dI/dx_i
/// for every variable. Constants are not recorded (node -1). For the 21-variable contact
/// integral this costs a fraction of forward mode with Dual<21>, which carries 21 derivatives
/// through every operation.
///
/// Usage: create a GradientTape, make it active with GradientTape::Scope, build variables with
/// ReverseScalar::variable(value, i), compute, then call tape.gradient(result, g).

#include <cmath>
#include <vector>

#include "sinew/contact/active_tape.hpp"

#include <Eigen/Core>

namespace sinew::contact {

class GradientTape {
 public:
  struct Node {
    int parent[2];
    double partial[2];
  };

  /// Makes `tape` the calling thread's active tape for the lifetime of the scope (and clears it).
  using Scope = ActiveTapeScope<GradientTape>;

  static GradientTape*& active() {
    thread_local GradientTape* tape = nullptr;
    return tape;
  }

  void clear() {
    nodes_.clear();
    variable_node_.clear();
  }
  int push(int a, double da, int b, double db) {
    nodes_.push_back(Node{{a, b}, {da, db}});
    return static_cast<int>(nodes_.size()) - 1;
  }
  int push_variable(int index) {
    if (index >= static_cast<int>(variable_node_.size())) variable_node_.resize(static_cast<std::size_t>(index) + 1, -1);
    const int node = push(-1, 0, -1, 0);
    variable_node_[static_cast<std::size_t>(index)] = node;
    return node;
  }

  /// dI/dx for the scalar recorded at node `result` (-1: a constant, zero gradient); variables
  /// never created get 0.
  template <int N>
  void gradient(int result, Eigen::Matrix<double, N, 1>& out) {
    out.setZero();
    if (result < 0) return;
    adjoint_.assign(nodes_.size(), 0.0);
    adjoint_[static_cast<std::size_t>(result)] = 1.0;
    for (int k = result; k >= 0; --k) {
      const double a = adjoint_[static_cast<std::size_t>(k)];
      if (a == 0) continue;
      const Node& node = nodes_[static_cast<std::size_t>(k)];
      if (node.parent[0] >= 0) adjoint_[static_cast<std::size_t>(node.parent[0])] += a * node.partial[0];
      if (node.parent[1] >= 0) adjoint_[static_cast<std::size_t>(node.parent[1])] += a * node.partial[1];
    }
    for (int i = 0; i < N && i < static_cast<int>(variable_node_.size()); ++i) {
      const int node = variable_node_[static_cast<std::size_t>(i)];
      if (node >= 0) out[i] = adjoint_[static_cast<std::size_t>(node)];
    }
  }

 private:
  std::vector<Node> nodes_;
  std::vector<int> variable_node_;
  std::vector<double> adjoint_;
};

/// A scalar recorded on the calling thread's active GradientTape; constants carry node -1. Each
/// recorded scalar keeps a pointer to its tape, so operations do not look up the thread's tape.
struct ReverseScalar {
  double v = 0;
  int node = -1;
  GradientTape* tape = nullptr;

  ReverseScalar() = default;
  ReverseScalar(double constant) : v(constant) {}  // NOLINT: constants convert implicitly
  static ReverseScalar variable(double value, int index) {
    ReverseScalar s(value);
    s.tape = GradientTape::active();
    s.node = s.tape->push_variable(index);
    return s;
  }

  friend ReverseScalar operator+(const ReverseScalar& a, const ReverseScalar& b) {
    return make(a.v + b.v, a, 1.0, b, 1.0);
  }
  friend ReverseScalar operator-(const ReverseScalar& a, const ReverseScalar& b) {
    return make(a.v - b.v, a, 1.0, b, -1.0);
  }
  friend ReverseScalar operator-(const ReverseScalar& a) { return make(-a.v, a, -1.0); }
  friend ReverseScalar operator*(const ReverseScalar& a, const ReverseScalar& b) {
    return make(a.v * b.v, a, b.v, b, a.v);
  }
  friend ReverseScalar operator*(const ReverseScalar& a, double s) { return make(a.v * s, a, s); }
  friend ReverseScalar operator*(double s, const ReverseScalar& a) { return a * s; }
  friend ReverseScalar operator/(const ReverseScalar& a, const ReverseScalar& b) {
    const double inv = 1.0 / b.v;
    const double q = a.v * inv;
    return make(q, a, inv, b, -q * inv);
  }
  friend ReverseScalar operator/(const ReverseScalar& a, double s) { return a * (1.0 / s); }
  friend ReverseScalar sqrt(const ReverseScalar& a) {
    const double r = std::sqrt(a.v);
    return make(r, a, 0.5 / r);
  }
  ReverseScalar& operator+=(const ReverseScalar& b) { return *this = *this + b; }

 private:
  static ReverseScalar make(double value, const ReverseScalar& a, double da) {
    ReverseScalar s(value);
    if (a.tape) {
      s.tape = a.tape;
      s.node = a.tape->push(a.node, da, -1, 0);
    }
    return s;
  }
  static ReverseScalar make(double value, const ReverseScalar& a, double da, const ReverseScalar& b, double db) {
    ReverseScalar s(value);
    if (a.tape || b.tape) {
      s.tape = a.tape ? a.tape : b.tape;
      s.node = s.tape->push(a.tape ? a.node : -1, a.tape ? da : 0, b.tape ? b.node : -1, b.tape ? db : 0);
    }
    return s;
  }
};

}  // namespace sinew::contact
