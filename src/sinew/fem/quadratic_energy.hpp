#pragma once
/// @file quadratic_energy.hpp
/// A quadratic term of the incremental potential of a time step:
///   E(x) = (s / 2) (x - c)ᵀ A (x - c),
/// A a constant symmetric 3#V x 3#V matrix stored as 3x3 node blocks (a mass matrix, a damping
/// matrix), c the center (#V x 3) and s a scale, both set per time step. Implicit Euler in
/// position form uses it twice (dissertation section 4.8, paper section 4):
///   inertia:   A = M, c = x_n + h v_n, s = 1 / h²  (M mass; energy unit)
///   viscosity: A = D, c = x_n,         s = 1 / h   (D damping, force × time / length)
/// so that the stationarity of Π(x) + inertia + viscosity is M (v_{n+1} - v_n) / h = -∇Π - D v_{n+1}.

#include <string>

#include <Eigen/SparseCore>

#include "sinew/core/energy.hpp"

namespace sinew::fem {

class QuadraticEnergy final : public Energy {
 public:
  /// `matrix`: symmetric, its pattern fixed. `name` appears in logs.
  QuadraticEnergy(std::string name, BlockSparseMatrix matrix);

  /// c (#V x 3) and s (>= 0). s = 0 switches the term off.
  void set_center_and_scale(Positions center, double scale);

  std::string_view name() const override { return name_; }
  double value(const Positions& x) const override;
  void add_gradient(const Positions& x, NodalVectors& grad) const override;
  void add_hessian(const Positions& x, BlockSparseMatrix& H) const override;
  void hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const override;
  void bind_pattern(const BlockSparseMatrix& H) override;
  bool has_hessian() const override { return scale_ != 0; }

  /// (1/2) vᵀ A v for nodal vectors v (#V x 3), e.g. the kinetic energy with A = M.
  double quadratic_form(const NodalVectors& v) const;
  /// A v for nodal vectors v (#V x 3).
  NodalVectors multiply(const NodalVectors& v) const;
  const BlockSparseMatrix& matrix() const { return matrix_; }

 private:
  std::string name_;
  BlockSparseMatrix matrix_;
  Positions center_;
  double scale_ = 0;
  std::vector<Index> target_;  ///< per block of matrix_, its index in the bound H
  const BlockSparseMatrix* bound_ = nullptr;
  std::uint64_t bound_version_ = 0;
};

/// a A + b B, the pattern the union of both (sizes must agree).
BlockSparseMatrix linear_combination(double a, const BlockSparseMatrix& A, double b, const BlockSparseMatrix& B);

/// The nodal mass matrix of `mass` (#V x #V scalar, block (a, b) = M(a, b) I3) as 3x3 blocks.
BlockSparseMatrix block_mass_matrix(const Eigen::SparseMatrix<double>& mass);

}  // namespace sinew::fem
