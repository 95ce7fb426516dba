#include "sinew/fem/quadratic_energy.hpp"

#include <stdexcept>

namespace sinew::fem {

QuadraticEnergy::QuadraticEnergy(std::string name, BlockSparseMatrix matrix)
    : name_(std::move(name)), matrix_(std::move(matrix)) {}

void QuadraticEnergy::set_center_and_scale(Positions center, double scale) {
  // Programming errors, not input: the solver passes a configuration of the model and a scale
  // 1/h or 1/h^2 of a time step h > 0.
  if (center.rows() != matrix_.num_nodes())
    throw std::invalid_argument("QuadraticEnergy: the center has " + std::to_string(center.rows()) +
                                " rows, the matrix " + std::to_string(matrix_.num_nodes()) + " nodes");
  if (!(scale >= 0)) throw std::invalid_argument("QuadraticEnergy: the scale must be >= 0");
  center_ = std::move(center);
  scale_ = scale;
}

NodalVectors QuadraticEnergy::multiply(const NodalVectors& v) const {
  NodalVectors out = NodalVectors::Zero(v.rows(), 3);
  const auto& offsets = matrix_.row_offsets();
  const auto& columns = matrix_.columns();
  const auto& values = matrix_.values();
  for (Index a = 0; a < matrix_.num_nodes(); ++a) {
    Vector3 sum = Vector3::Zero();
    for (Index k = offsets[static_cast<std::size_t>(a)]; k < offsets[static_cast<std::size_t>(a) + 1]; ++k)
      sum += values[static_cast<std::size_t>(k)] * v.row(columns[static_cast<std::size_t>(k)]).transpose();
    out.row(a) = sum.transpose();
  }
  return out;
}

double QuadraticEnergy::quadratic_form(const NodalVectors& v) const {
  return 0.5 * (v.array() * multiply(v).array()).sum();
}

double QuadraticEnergy::value(const Positions& x) const {
  if (scale_ == 0) return 0;
  return scale_ * quadratic_form(x - center_);
}

void QuadraticEnergy::add_gradient(const Positions& x, NodalVectors& grad) const {
  if (scale_ == 0) return;
  grad += scale_ * multiply(x - center_);
}

void QuadraticEnergy::hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const {
  const auto& offsets = matrix_.row_offsets();
  const auto& columns = matrix_.columns();
  for (Index a = 0; a < matrix_.num_nodes(); ++a)
    for (Index k = offsets[static_cast<std::size_t>(a)]; k < offsets[static_cast<std::size_t>(a) + 1]; ++k)
      if (columns[static_cast<std::size_t>(k)] > a) pairs.emplace_back(a, columns[static_cast<std::size_t>(k)]);
}

void QuadraticEnergy::bind_pattern(const BlockSparseMatrix& H) {
  const auto& offsets = matrix_.row_offsets();
  const auto& columns = matrix_.columns();
  target_.assign(columns.size(), -1);
  for (Index a = 0; a < matrix_.num_nodes(); ++a)
    for (Index k = offsets[static_cast<std::size_t>(a)]; k < offsets[static_cast<std::size_t>(a) + 1]; ++k)
      target_[static_cast<std::size_t>(k)] = H.find(a, columns[static_cast<std::size_t>(k)]);
  bound_ = &H;
  bound_version_ = H.pattern_version();
}

void QuadraticEnergy::add_hessian(const Positions& /*x*/, BlockSparseMatrix& H) const {
  if (scale_ == 0) return;
  if (bound_ != &H || bound_version_ != H.pattern_version())
    throw std::logic_error("QuadraticEnergy::add_hessian: bind_pattern() was not called for this matrix");
  const auto& values = matrix_.values();
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (target_[k] < 0) throw std::logic_error("QuadraticEnergy::add_hessian: a block is missing from the pattern");
    H.add(target_[k], scale_ * values[k]);
  }
}

BlockSparseMatrix linear_combination(double a, const BlockSparseMatrix& A, double b, const BlockSparseMatrix& B) {
  // Programming error, not input: both matrices are assembled over the same mesh.
  if (A.num_nodes() != B.num_nodes()) throw std::invalid_argument("linear_combination: matrices of different sizes");
  std::vector<std::pair<Index, Index>> pairs;
  for (const BlockSparseMatrix* M : {&A, &B})
    for (Index r = 0; r < M->num_nodes(); ++r)
      for (Index k = M->row_offsets()[static_cast<std::size_t>(r)]; k < M->row_offsets()[static_cast<std::size_t>(r) + 1]; ++k)
        pairs.emplace_back(r, M->columns()[static_cast<std::size_t>(k)]);
  BlockSparseMatrix C;
  C.set_pattern(A.num_nodes(), pairs);
  for (const auto& [s, M] : {std::pair<double, const BlockSparseMatrix*>{a, &A}, {b, &B}})
    for (Index r = 0; r < M->num_nodes(); ++r)
      for (Index k = M->row_offsets()[static_cast<std::size_t>(r)]; k < M->row_offsets()[static_cast<std::size_t>(r) + 1]; ++k)
        C.add(C.find(r, M->columns()[static_cast<std::size_t>(k)]), s * M->values()[static_cast<std::size_t>(k)]);
  return C;
}

BlockSparseMatrix block_mass_matrix(const Eigen::SparseMatrix<double>& mass) {
  std::vector<std::pair<Index, Index>> pairs;
  for (int col = 0; col < mass.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(mass, col); it; ++it)
      if (it.row() != it.col()) pairs.emplace_back(static_cast<Index>(it.row()), static_cast<Index>(it.col()));
  BlockSparseMatrix M;
  M.set_pattern(static_cast<Index>(mass.rows()), pairs);
  for (int col = 0; col < mass.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(mass, col); it; ++it)
      M.add(M.find(static_cast<Index>(it.row()), static_cast<Index>(it.col())), it.value() * Matrix3::Identity());
  return M;
}

}  // namespace sinew::fem
