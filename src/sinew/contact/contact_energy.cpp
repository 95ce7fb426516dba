#include "sinew/contact/contact_energy.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "sinew/core/error.hpp"

namespace sinew::contact {

double contact_energy_value(const CollisionSet& collisions, const Positions& x, const std::vector<std::size_t>& which) {
  if (collisions.overflowed()) return std::numeric_limits<double>::infinity();
  const auto& pairs = collisions.pairs();
  const PairIntegrator& integrator = collisions.integrator();
  std::vector<double> values(which.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, which.size(), 64), [&](const auto& range) {
    for (std::size_t k = range.begin(); k != range.end(); ++k) {
      const ActivePair& p = pairs.at(which[k]);
      values[k] = 0.5 * p.penalty * integrator.integral(collisions.pair_geometry_at(x, p), p.support);
    }
  });
  return std::accumulate(values.begin(), values.end(), 0.0);
}

double contact_energy_value(const CollisionSet& collisions, const Positions& x) {
  std::vector<std::size_t> all(collisions.pairs().size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  return contact_energy_value(collisions, x, all);
}

PairVector pair_energy_gradient(const CollisionSet& collisions, const ActivePair& pair, const Positions& x) {
  PairVector gradient;
  collisions.integrator().integral_gradient(collisions.pair_geometry_at(x, pair), pair.support, gradient);
  gradient *= 0.5 * pair.penalty;
  return gradient;
}

ContactEnergy::ContactEnergy(ContactGeometry geometry, ContactOptions options)
    : options_(options), collisions_(std::move(geometry), options.method, options.candidate_cap) {}

void ContactEnergy::require_current(const Positions& x) const {
  if (!collisions_.is_current(x))
    throw std::logic_error("ContactEnergy: update(x) must be called before evaluating at a new x");
}

void ContactEnergy::begin_step(const Positions& x) { collisions_.rebuild(x); }

void ContactEnergy::update(const Positions& x) { collisions_.update(x); }

bool ContactEnergy::is_valid(const Positions& x) const {
  require_current(x);
  return !collisions_.overflowed();
}

void ContactEnergy::set_share(std::vector<int> tet_owner, int part, PairJoin join) {
  if (!tet_owner.empty() && tet_owner.size() != static_cast<std::size_t>(geometry().tets.rows()))
    throw Error(fmt::format("contact: {} tet owners for {} tets", tet_owner.size(), geometry().tets.rows()));
  tet_owner_ = std::move(tet_owner);
  share_part_ = part;
  CollisionShare detection;
  if (!tet_owner_.empty() && join) {
    detection.detects_tet.resize(tet_owner_.size());
    for (std::size_t t = 0; t < tet_owner_.size(); ++t) detection.detects_tet[t] = tet_owner_[t] == part;
    detection.join = std::move(join);
  }
  collisions_.set_share(std::move(detection));
}

std::vector<std::size_t> ContactEnergy::shared_pairs() const {
  const auto& pairs = collisions_.pairs();
  std::vector<std::size_t> mine;
  mine.reserve(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k)
    if (tet_owner_.empty() || tet_owner_[static_cast<std::size_t>(pairs[k].tet)] == share_part_) mine.push_back(k);
  return mine;
}

double ContactEnergy::value(const Positions& x) const {
  require_current(x);
  return contact_energy_value(collisions_, x, shared_pairs());
}

void ContactEnergy::add_gradient(const Positions& x, NodalVectors& grad) const {
  require_current(x);
  if (collisions_.overflowed())
    throw Error(fmt::format("contact: {} candidate pairs at this configuration (more than the cap): the bodies "
                            "overlap far beyond what contact can resolve",
                            collisions_.times().candidates));
  const auto& pairs = collisions_.pairs();
  const std::vector<std::size_t> mine = shared_pairs();
  std::vector<PairVector> gradients(mine.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mine.size(), 64), [&](const auto& range) {
    for (std::size_t k = range.begin(); k != range.end(); ++k)
      gradients[k] = pair_energy_gradient(collisions_, pairs[mine[k]], x);
  });
  for (std::size_t k = 0; k < mine.size(); ++k) {
    const auto nodes = collisions_.nodes(pairs[mine[k]]);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      grad.row(nodes[i]) += gradients[k].segment<3>(3 * static_cast<Index>(i)).transpose();
  }
}

void ContactEnergy::hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const {
  collisions_.append_pattern(pairs);
}

void ContactEnergy::add_hessian(const Positions& x, BlockSparseMatrix& H) const {
  require_current(x);
  const auto& pairs = collisions_.pairs();
  const PairIntegrator& integrator = collisions_.integrator();
  // In chunks: pair Hessians and their block indices in parallel, then a serial scatter (which
  // is cheap), so memory stays bounded by the chunk.
  constexpr std::size_t kChunk = 2048;
  const std::vector<std::size_t> mine = shared_pairs();
  std::vector<PairMatrix> hessians(std::min(kChunk, mine.size()));
  std::vector<std::array<Index, 49>> blocks(hessians.size());
  for (std::size_t begin = 0; begin < mine.size(); begin += kChunk) {
    const std::size_t end = std::min(mine.size(), begin + kChunk);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, 16), [&](const auto& range) {
      PairVector gradient;
      for (std::size_t k = range.begin(); k != range.end(); ++k) {
        const ActivePair& p = pairs[mine[k]];
        PairMatrix& hessian = hessians[k - begin];
        integrator.integral_hessian(collisions_.pair_geometry_at(x, p), p.support, options_.hessian,
                                    pair_unknowns(collisions_.geometry(), p.triangle, p.tet), gradient, hessian);
        hessian *= 0.5 * p.penalty;
        const auto nodes = collisions_.nodes(p);
        for (std::size_t i = 0; i < 7; ++i)
          for (std::size_t j = 0; j < 7; ++j) blocks[k - begin][7 * i + j] = H.find(nodes[i], nodes[j]);
      }
    });
    for (std::size_t k = begin; k < end; ++k)
      for (int i = 0; i < 7; ++i)
        for (int j = 0; j < 7; ++j) {
          const Index b = blocks[k - begin][static_cast<std::size_t>(7 * i + j)];
          if (b < 0) throw std::logic_error("ContactEnergy::add_hessian: a contact block is missing from the pattern");
          H.add(b, hessians[k - begin].block<3, 3>(3 * i, 3 * j));
        }
  }
}

}  // namespace sinew::contact
