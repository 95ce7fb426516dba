#pragma once
/// @file energy.hpp
/// One interface for every term of the total potential (elastic, external loads, contact,
/// inertia): value, gradient, sparse Hessian, step validity. Newton sees only their sum.
/// All terms work on full node positions x (#V x 3); constraints and rigid bodies are the
/// DofMap's business, not the energies'.

#include <string_view>
#include <utility>
#include <vector>

#include "sinew/fem/block_sparse_matrix.hpp"

namespace sinew::fem {

/// Gradient storage: #V x 3, same layout as Positions (force unit).
using NodalVectors = Positions;

class Energy {
 public:
  virtual ~Energy() = default;
  virtual std::string_view name() const = 0;

  /// Energy at positions x (#V x 3). +infinity for an illegal configuration.
  virtual double value(const Positions& x) const = 0;
  /// grad += dE/dx (#V x 3).
  virtual void add_gradient(const Positions& x, NodalVectors& grad) const = 0;
  /// H += d2E/dx2 into blocks of the pattern announced by hessian_pattern().
  virtual void add_hessian(const Positions& x, BlockSparseMatrix& H) const = 0;
  /// Node pairs (a, b) whose 3x3 block this term may fill (one orientation suffices).
  virtual void hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const = 0;
  /// Called after the Hessian's pattern was (re)built, before add_hessian(): terms may cache
  /// block indices here.
  virtual void bind_pattern(const BlockSparseMatrix& /*H*/) {}
  /// False when x is not an admissible configuration (e.g. an inverted element).
  virtual bool is_valid(const Positions& /*x*/) const { return true; }
  /// The load parameter lambda in [0, 1] (statics) or time (dynamics) changed.
  virtual void set_load_parameter(double /*lambda*/) {}
  /// True when the Hessian has nothing to add (linear terms).
  virtual bool has_hessian() const { return true; }
};

}  // namespace sinew::fem
