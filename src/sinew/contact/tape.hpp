#pragma once
/// @file tape.hpp
/// Exact Hessians by reverse mode over forward mode: TapeScalar<N> records every operation of a
/// scalar computation on a tape, each node holding its value as a Dual<N> number, the operation
/// and its (at most two) operands; constants take no node. Sweeping the tape backwards with
/// Dual<N> adjoints, each node's local partials derived from its operation and its operands'
/// values, yields for each independent variable x_i dI/dx_i (the adjoint's value) and the Hessian
/// row d²I/dx_i dx (the adjoint's gradient part). Cost: a few times one Dual<N> evaluation, 3-4
/// times less than propagating full N x N Hessians forward (measured for N = 21: 67-87 us against
/// 263 us per contact pair, before constants left the tape and partials stopped being stored).
///
/// Usage: create a Tape, make it active with Tape::Scope, build variables with
/// TapeScalar::variable(value, i) and compute; then call tape.gradient_and_hessian(result, ...).
/// One active tape per thread; a tape is reused across evaluations (clear() keeps its memory).

#include <cmath>
#include <vector>

#include "sinew/contact/active_tape.hpp"

#include "sinew/contact/dual.hpp"

namespace sinew::contact {

template <int N>
class Tape {
 public:
  using D = Dual<N>;
  /// How a node's value came from its parents; the reverse sweep derives the local partials from
  /// it and the parents' values (stored partials would triple a node's size).
  enum class Op : unsigned char {
    Leaf,         ///< an independent variable
    Add,          ///< a + b
    Subtract,     ///< a - b
    Negate,       ///< -a
    Multiply,     ///< a * b
    Scale,        ///< a * scalar (also a constant times a, a / constant)
    Shift,        ///< a + constant (also constant + a, a - constant)
    ReverseShift, ///< constant - a
    Divide,       ///< a / b
    Reciprocal,   ///< constant / a (the constant in `scalar`)
    SquareRoot,   ///< sqrt(a)
  };
  struct Node {
    D value;
    int parent[2] = {-1, -1};
    Op op = Op::Leaf;
    double scalar = 0;  ///< Scale's factor, Reciprocal's numerator
  };

  /// Makes `tape` the calling thread's active tape for the lifetime of the scope (and clears it).
  using Scope = ActiveTapeScope<Tape>;

  static Tape*& active() {
    thread_local Tape* tape = nullptr;
    return tape;
  }

  void clear() {
    nodes_.clear();
    variable_node_.assign(N, -1);
  }
  int push(const D& value, Op op, int a = -1, int b = -1, double scalar = 0) {
    Node& node = nodes_.emplace_back();
    node.value = value;
    node.op = op;
    node.parent[0] = a;
    node.parent[1] = b;
    node.scalar = scalar;
    return static_cast<int>(nodes_.size()) - 1;
  }
  void mark_variable(int i, int node) { variable_node_[static_cast<std::size_t>(i)] = node; }
  const D& value(int node) const { return nodes_[static_cast<std::size_t>(node)].value; }

  /// Gradient and Hessian of the scalar at `result` with respect to the N variables (variables
  /// never created have zero rows; a result that is a constant, node -1, has zero derivatives).
  void gradient_and_hessian(int result, Eigen::Matrix<double, N, 1>& gradient, Eigen::Matrix<double, N, N>& hessian) {
    gradient.setZero();
    hessian.setZero();
    if (result < 0) return;
    adjoint_.assign(static_cast<std::size_t>(result) + 1, D(0.0));
    touched_.assign(static_cast<std::size_t>(result) + 1, 0);
    adjoint_[static_cast<std::size_t>(result)] = D(1.0);
    touched_[static_cast<std::size_t>(result)] = 1;
    for (int k = result; k >= 0; --k) {
      const auto K = static_cast<std::size_t>(k);
      if (!touched_[K]) continue;
      propagate(nodes_[K], adjoint_[K]);
    }
    for (int i = 0; i < N; ++i) {
      const int node = variable_node_[static_cast<std::size_t>(i)];
      if (node < 0 || node > result) continue;
      gradient[i] = adjoint_[static_cast<std::size_t>(node)].v;
      hessian.row(i) = adjoint_[static_cast<std::size_t>(node)].d.transpose();
    }
  }

 private:
  /// adjoint(parent) += adjoint(node) * d node / d parent, for each parent in order. The
  /// partials are computed as the forward operation's Dual arithmetic would give them.
  void propagate(const Node& node, const D& adjoint) {
    const auto add = [&](int parent, const D& contribution) {
      adjoint_[static_cast<std::size_t>(parent)] += contribution;
      touched_[static_cast<std::size_t>(parent)] = 1;
    };
    const int a = node.parent[0], b = node.parent[1];
    switch (node.op) {
      case Op::Leaf:
        return;
      case Op::Add:
        add(a, adjoint);
        add(b, adjoint);
        return;
      case Op::Subtract:
        add(a, adjoint);
        add(b, -adjoint);
        return;
      case Op::Negate:
      case Op::ReverseShift:
        add(a, -adjoint);
        return;
      case Op::Shift:
        add(a, adjoint);
        return;
      case Op::Multiply:
        add(a, adjoint * value(b));
        add(b, adjoint * value(a));
        return;
      case Op::Scale:
        add(a, adjoint * node.scalar);
        return;
      case Op::Divide: {
        const D inv = D(1.0) / value(b);
        add(a, adjoint * inv);
        add(b, adjoint * (-(node.value * inv)));
        return;
      }
      case Op::Reciprocal: {  // c / a: d/da = -(c / a) / a
        const D inv = D(1.0) / value(a);
        add(a, adjoint * (-(node.value * inv)));
        return;
      }
      case Op::SquareRoot:
        add(a, adjoint * (D(0.5) / node.value));
        return;
    }
  }

  std::vector<Node> nodes_;
  std::vector<int> variable_node_;
  std::vector<D> adjoint_;
  std::vector<char> touched_;
};

/// A scalar recorded on the calling thread's active Tape<N>, or a constant (node -1), which
/// takes no place on the tape: an operation with a constant operand records one node with one
/// parent, and one on two constants records nothing.
template <int N>
struct TapeScalar {
  using T = Tape<N>;
  using D = Dual<N>;
  using Op = typename T::Op;
  int node = -1;
  double constant = 0;  ///< the value when node < 0

  TapeScalar() = default;
  TapeScalar(double value) : constant(value) {}  // NOLINT: constants convert implicitly
  static TapeScalar from_node(int n) {
    TapeScalar s;
    s.node = n;
    return s;
  }
  static TapeScalar variable(double value, int i) {
    const int n = T::active()->push(D::variable(value, i), Op::Leaf);
    T::active()->mark_variable(i, n);
    return from_node(n);
  }
  bool is_constant() const { return node < 0; }
  /// The value and gradient (a constant's gradient is zero).
  D dual() const { return is_constant() ? D(constant) : T::active()->value(node); }
  double v() const { return is_constant() ? constant : T::active()->value(node).v; }

  friend TapeScalar operator+(const TapeScalar& a, const TapeScalar& b) {
    if (a.is_constant() && b.is_constant()) return a.constant + b.constant;
    if (b.is_constant()) return record(recorded(a) + D(b.constant), Op::Shift, a.node);
    if (a.is_constant()) return record(D(a.constant) + recorded(b), Op::Shift, b.node);
    return record(recorded(a) + recorded(b), Op::Add, a.node, b.node);
  }
  friend TapeScalar operator-(const TapeScalar& a, const TapeScalar& b) {
    if (a.is_constant() && b.is_constant()) return a.constant - b.constant;
    if (b.is_constant()) return record(recorded(a) - D(b.constant), Op::Shift, a.node);
    if (a.is_constant()) return record(D(a.constant) - recorded(b), Op::ReverseShift, b.node);
    return record(recorded(a) - recorded(b), Op::Subtract, a.node, b.node);
  }
  friend TapeScalar operator-(const TapeScalar& a) {
    if (a.is_constant()) return -a.constant;
    return record(-recorded(a), Op::Negate, a.node);
  }
  friend TapeScalar operator*(const TapeScalar& a, const TapeScalar& b) {
    if (a.is_constant() && b.is_constant()) return a.constant * b.constant;
    if (b.is_constant()) return a * b.constant;
    if (a.is_constant()) return record(D(a.constant) * recorded(b), Op::Scale, b.node, -1, a.constant);
    return record(recorded(a) * recorded(b), Op::Multiply, a.node, b.node);
  }
  friend TapeScalar operator*(const TapeScalar& a, double s) {
    if (a.is_constant()) return a.constant * s;
    return record(recorded(a) * s, Op::Scale, a.node, -1, s);
  }
  friend TapeScalar operator*(double s, const TapeScalar& a) { return a * s; }
  friend TapeScalar operator/(const TapeScalar& a, const TapeScalar& b) {
    // a * (1 / b), as Dual's division rounds it.
    if (a.is_constant() && b.is_constant()) return a.constant * (1.0 / b.constant);
    if (b.is_constant()) return a * (1.0 / b.constant);
    const D inv = D(1.0) / recorded(b);
    if (a.is_constant()) return record(D(a.constant) * inv, Op::Reciprocal, b.node, -1, a.constant);
    return record(recorded(a) * inv, Op::Divide, a.node, b.node);
  }
  friend TapeScalar operator/(const TapeScalar& a, double s) { return a * (1.0 / s); }
  friend TapeScalar sqrt(const TapeScalar& a) {
    if (a.is_constant()) return std::sqrt(a.constant);
    return record(sqrt(recorded(a)), Op::SquareRoot, a.node);
  }
  TapeScalar& operator+=(const TapeScalar& b) { return *this = *this + b; }

 private:
  /// The recorded value of a scalar on the tape (not a constant).
  static const D& recorded(const TapeScalar& s) { return T::active()->value(s.node); }
  static TapeScalar record(const D& value, Op op, int a, int b = -1, double scalar = 0) {
    return from_node(T::active()->push(value, op, a, b, scalar));
  }
};

}  // namespace sinew::contact
