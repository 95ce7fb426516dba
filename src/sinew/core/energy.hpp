#pragma once
/// @file energy.hpp
/// One interface for every term of the total potential (elastic, external loads, contact,
/// inertia): value, gradient, sparse Hessian, step validity. Newton sees only their sum.
/// All terms work on full node positions x (#V x 3); constraints and rigid bodies are the
/// DofMap's business, not the energies'.

#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "sinew/core/block_sparse_matrix.hpp"

namespace sinew {

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
  /// On several MPI ranks, for a term that holds one rank's share of itself (docs/mpi.md): the
  /// pattern of the whole term, the same on every rank, which a Hessian summed over the ranks
  /// lies on. By default hessian_pattern().
  virtual void whole_hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const { hessian_pattern(pairs); }
  /// Called after the Hessian's pattern was (re)built, before add_hessian(): terms may cache
  /// block indices here.
  virtual void bind_pattern(const BlockSparseMatrix& /*H*/) {}
  /// False when x is not an admissible configuration (e.g. an inverted element).
  virtual bool is_valid(const Positions& /*x*/) const { return true; }
  /// The load parameter lambda in [0, 1] (statics) or time (dynamics) changed.
  virtual void set_load_parameter(double /*lambda*/) {}
  /// Time stepping: the size h (time, > 0) of the step about to be attempted, before its
  /// begin_step (terms with a rate-dependent setting, such as a slip velocity, scale it by h).
  virtual void set_time_step(double /*h*/) {}
  /// True when the Hessian has nothing to add (linear terms).
  virtual bool has_hessian() const { return true; }

  /// The state moved to x (#V x 3): terms whose value depends on x-dependent bookkeeping
  /// (contact pairs) refresh it here. Called by the objective before value(), add_gradient(),
  /// add_hessian() or is_valid() at a new x; cheap to call again with the same x.
  virtual void update(const Positions& /*x*/) {}
  /// A load or time step starts from the converged positions x (#V x 3): terms may rebuild
  /// acceleration structures here (the contact BVH), then update(x) follows.
  virtual void begin_step(const Positions& /*x*/) {}
  /// Incremented whenever hessian_pattern() would return pairs not returned before (contact
  /// pairs appearing); the objective then rebuilds the Hessian's pattern. Constant for terms
  /// with a fixed pattern.
  virtual std::uint64_t pattern_revision() const { return 0; }
};

}  // namespace sinew
