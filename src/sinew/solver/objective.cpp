#include "sinew/solver/objective.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace sinew::solver {

Objective::Objective(const fem::DofMap& dofs, std::vector<Energy*> terms, Index num_nodes)
    : dofs_(dofs), reduction_(dofs), terms_(std::move(terms)), num_nodes_(num_nodes) {}

void Objective::set_load_parameter(double lambda) {
  for (auto* term : terms_) term->set_load_parameter(lambda);
}

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void Objective::update_terms(const fem::State& state) {
  if (!state.x.allFinite()) return;
  const auto start = std::chrono::steady_clock::now();
  for (auto* term : terms_) term->update(state.x);
  collision_seconds_ += seconds_since(start);
}

void Objective::set_time_step(double h) {
  for (auto* term : terms_) term->set_time_step(h);
}

void Objective::begin_step(const fem::State& state) {
  if (!state.x.allFinite()) return;
  const auto start = std::chrono::steady_clock::now();
  for (auto* term : terms_) term->begin_step(state.x);
  collision_seconds_ += seconds_since(start);
}

std::uint64_t Objective::pattern_revisions() const {
  std::uint64_t sum = 0;
  for (auto* term : terms_) sum += term->pattern_revision();
  return sum;
}

bool Objective::is_valid(const fem::State& state) {
  if (!state.x.allFinite()) return false;
  update_terms(state);
  for (auto* term : terms_)
    if (!term->is_valid(state.x)) return false;
  return true;
}

double Objective::value(const fem::State& state) {
  if (!is_valid(state)) return std::numeric_limits<double>::infinity();
  double sum = 0;
  for (auto* term : terms_) sum += term->value(state.x);
  return std::isnan(sum) ? std::numeric_limits<double>::infinity() : sum;
}

NodalVectors Objective::full_gradient(const fem::State& state, double* force_scale) {
  NodalVectors g = NodalVectors::Zero(num_nodes_, 3);
  update_terms(state);
  if (!force_scale) {
    for (auto* term : terms_) term->add_gradient(state.x, g);
    return g;
  }
  *force_scale = 0;
  NodalVectors term_gradient(num_nodes_, 3);
  for (auto* term : terms_) {
    term_gradient.setZero();
    term->add_gradient(state.x, term_gradient);
    *force_scale = std::max(*force_scale, term_gradient.norm());
    g += term_gradient;
  }
  return g;
}

void Objective::rebuild_pattern() {
  std::vector<std::pair<Index, Index>> pairs;
  for (auto* term : terms_) term->hessian_pattern(pairs);
  H_.set_pattern(num_nodes_, std::move(pairs));
  for (auto* term : terms_) term->bind_pattern(H_);
  reduction_.bind(H_);
  pattern_ready_ = true;
  pattern_revision_ = pattern_revisions();
}

bool Objective::hessian(const fem::State& state, const NodalVectors& full_gradient,
                        const VectorX& node_viscosity, fem::SparseMatrix& K) {
  bool fresh = false;
  update_terms(state);
  if (!pattern_ready_ || pattern_revisions() != pattern_revision_) {
    rebuild_pattern();
    fresh = true;
  }
  H_.set_zero();
  for (auto* term : terms_)
    if (term->has_hessian()) term->add_hessian(state.x, H_);
  const auto nnz_before = K.nonZeros();
  const auto rows_before = K.rows();
  reduction_.reduce(state, H_, full_gradient, node_viscosity, K);
  return fresh || K.nonZeros() != nnz_before || K.rows() != rows_before;
}

}  // namespace sinew::solver
