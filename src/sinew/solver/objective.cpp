#include "sinew/solver/objective.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "sinew/core/error.hpp"
#include "sinew/parallel/ranks.hpp"

namespace sinew::solver {

Objective::Objective(const fem::DofMap& dofs, std::vector<Energy*> terms, Index num_nodes)
    : dofs_(dofs), reduction_(dofs), terms_(std::move(terms)), num_nodes_(num_nodes) {}

void Objective::share_terms(std::vector<bool> shared) {
  if (shared.size() != terms_.size()) throw Error("Objective::share_terms: one flag per term is needed");
  shared_ = std::move(shared);
  pattern_ready_ = false;  // the pattern is each rank's own or the whole
}

Energy* Objective::evaluated(std::size_t i) const {
  if (shared_.empty() || shared_[i]) return terms_[i];
  return parallel::is_root() ? terms_[i] : nullptr;
}

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
  if (!state.x.allFinite()) return false;  // the same on every rank: x is
  update_terms(state);
  bool valid = true;
  // A shared term is checked by each rank for its own elements; the others everywhere.
  for (std::size_t i = 0; i < terms_.size() && valid; ++i) valid = terms_[i]->is_valid(state.x);
  return shared_.empty() ? valid : parallel::all(valid);
}

double Objective::value(const fem::State& state) {
  if (!is_valid(state)) return std::numeric_limits<double>::infinity();
  double sum = 0;
  for (std::size_t i = 0; i < terms_.size(); ++i)
    if (Energy* term = evaluated(i)) sum += term->value(state.x);
  if (!shared_.empty()) sum = parallel::sum(sum);  // a NaN on any rank stays NaN
  return std::isnan(sum) ? std::numeric_limits<double>::infinity() : sum;
}

NodalVectors Objective::full_gradient(const fem::State& state, double* force_scale) {
  NodalVectors g = NodalVectors::Zero(num_nodes_, 3);
  update_terms(state);
  if (!force_scale) {
    for (std::size_t i = 0; i < terms_.size(); ++i)
      if (Energy* term = evaluated(i)) term->add_gradient(state.x, g);
    if (!shared_.empty()) parallel::sum(g.data(), static_cast<std::size_t>(g.size()));
    return g;
  }
  *force_scale = 0;
  NodalVectors term_gradient(num_nodes_, 3);
  for (std::size_t i = 0; i < terms_.size(); ++i) {
    term_gradient.setZero();
    if (Energy* term = evaluated(i)) term->add_gradient(state.x, term_gradient);
    // Each term's norm is that of its whole gradient, summed over the ranks.
    if (!shared_.empty()) parallel::sum(term_gradient.data(), static_cast<std::size_t>(term_gradient.size()));
    *force_scale = std::max(*force_scale, term_gradient.norm());
    g += term_gradient;
  }
  return g;
}

void Objective::set_hessian_summed(bool summed) {
  if (summed != hessian_summed_) pattern_ready_ = false;  // the pattern is the whole or a part
  hessian_summed_ = summed;
}

void Objective::rebuild_pattern() {
  std::vector<std::pair<Index, Index>> pairs;
  if (assembles_parts()) {
    // Only what this rank evaluates (docs/mpi.md, "Each rank adds its part of the tangent"); the
    // diagonal blocks of every node come with set_pattern, so the ranks' K share their diagonal.
    for (std::size_t i = 0; i < terms_.size(); ++i)
      if (Energy* term = evaluated(i)) term->hessian_pattern(pairs);
    H_.set_pattern(num_nodes_, std::move(pairs));
    for (std::size_t i = 0; i < terms_.size(); ++i)
      if (Energy* term = evaluated(i)) term->bind_pattern(H_);
  } else {
    for (auto* term : terms_) term->whole_hessian_pattern(pairs);  // the same on every rank
    H_.set_pattern(num_nodes_, std::move(pairs));
    for (auto* term : terms_) term->bind_pattern(H_);
  }
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
  for (std::size_t i = 0; i < terms_.size(); ++i) {
    Energy* term = evaluated(i);
    if (term && term->has_hessian()) term->add_hessian(state.x, H_);
  }
  const auto nnz_before = K.nonZeros();
  const auto rows_before = K.rows();
  // Every rank gets the whole full-space Hessian (the same pattern everywhere: the terms give
  // it) and reduces it to the same K; or, with set_hessian_summed(false), its part (on its own
  // pattern), where the reduction's terms that do not come from H (viscosity, rigid-body
  // rotation) are rank 0's.
  const bool whole = shared_.empty() || hessian_summed_;
  if (!shared_.empty() && hessian_summed_)
    parallel::sum(H_.values().empty() ? nullptr : H_.values().front().data(), 9 * H_.values().size());
  if (whole || parallel::is_root())
    reduction_.reduce(state, H_, full_gradient, node_viscosity, K);
  else
    reduction_.reduce(state, H_, NodalVectors::Zero(full_gradient.rows(), 3), VectorX(), K);
  fresh = fresh || K.nonZeros() != nnz_before || K.rows() != rows_before;
  // The ranks' parts differ, and a new pattern is analyzed by all of them together.
  return assembles_parts() ? parallel::any(fresh) : fresh;
}

}  // namespace sinew::solver
