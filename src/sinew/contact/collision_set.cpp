#include "sinew/contact/collision_set.hpp"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "sinew/collision/broad_phase.hpp"
#include "sinew/contact/node_pair_key.hpp"
#include "sinew/core/error.hpp"

namespace sinew::contact {
namespace {

std::uint64_t key(Index a, Index b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

CollisionSet::CollisionSet(std::shared_ptr<const ContactGeometry> geometry, ContactMethod method,
                           std::size_t candidate_cap)
    : geometry_(std::move(geometry)), integrator_(&pair_integrator(method)) {
  if (!geometry_) throw std::invalid_argument("CollisionSet: no geometry");  // programming error, not input
  const ContactGeometry& g = *geometry_;
  validate_contact_geometry(g);
  candidate_cap_ =
      candidate_cap > 0 ? candidate_cap : std::max<std::size_t>(100000, 20 * static_cast<std::size_t>(g.tets.rows()));
  tet_has_depth_.resize(static_cast<std::size_t>(g.tets.rows()));
  for (Index t = 0; t < g.tets.rows(); ++t) {
    double m = 0;
    for (int k = 0; k < 4; ++k) m = std::max(m, g.depth[g.tets(t, k)]);
    tet_has_depth_[static_cast<std::size_t>(t)] = m > 0;
  }
  assign_trees();
}

void CollisionSet::assign_trees() {
  const ContactGeometry& g = *geometry_;
  const auto num_bodies = static_cast<std::size_t>(g.penalty.rows());
  trees_.assign(num_bodies, {});
  for (Index t = 0; t < g.tets.rows(); ++t) {
    const auto k = static_cast<std::size_t>(t);
    if (tet_has_depth_[k] && (share_.detects_tet.empty() || share_.detects_tet[k]))
      trees_[static_cast<std::size_t>(g.tet_body[t])].tets.push_back(t);
  }
  // Which penalties are positive never changes (set_penalty).
  trees_of_body_.assign(num_bodies, {});
  for (std::size_t a = 0; a < num_bodies; ++a)
    for (std::size_t b = 0; b < num_bodies; ++b)
      if (g.penalty(static_cast<Index>(a), static_cast<Index>(b)) > 0 && !trees_[b].tets.empty())
        trees_of_body_[a].push_back(static_cast<int>(b));
  tree_built_ = false;
}

void CollisionSet::set_share(CollisionShare share) {
  if (!share.detects_tet.empty()) {
    if (share.detects_tet.size() != tet_has_depth_.size())
      throw Error(fmt::format("collision: {} tet flags for {} tets", share.detects_tet.size(), tet_has_depth_.size()));
    if (!share.join) throw Error("collision: a share of the tets without a way to join the parts' pairs");
  }
  share_ = share.detects_tet.empty() ? CollisionShare{} : std::move(share);
  assign_trees();
  positions_.resize(0, 3);  // the next update recomputes the pairs (on every part)
}

void CollisionSet::fit_trees(const Positions& x, bool rebuild) {
  for (collision::TetSubsetTree& t : trees_) {
    const std::vector<collision::Aabb> boxes = collision::subset_boxes(x, geometry_->tets, t.tets);
    if (rebuild)
      t.tree.build(boxes);
    else
      t.tree.refit(boxes);
  }
  tree_built_ = true;
}

CollisionSet::CollisionSet(ContactGeometry geometry, ContactMethod method, std::size_t candidate_cap)
    : CollisionSet(std::make_shared<const ContactGeometry>(std::move(geometry)), method, candidate_cap) {}

void CollisionSet::check_size(const Positions& x, const char* caller) const {
  if (x.rows() != geometry_->depth.size())
    // Programming error, not input: the solver passes configurations of the contact geometry's mesh.
    throw std::invalid_argument(fmt::format("{}: x has {} rows, the contact geometry {} nodes", caller, x.rows(),
                                            geometry_->depth.size()));
}

bool CollisionSet::is_current(const Positions& x) const {
  return x.rows() == positions_.rows() && (x.array() == positions_.array()).all();
}

void CollisionSet::rebuild(const Positions& x) {
  check_size(x, "CollisionSet::rebuild");
  fit_trees(x, /*rebuild=*/true);
  positions_.resize(0, 3);  // force update() to recompute the pairs
  update(x);
}

void CollisionSet::update(const Positions& x) {
  if (is_current(x)) return;
  check_size(x, "CollisionSet::update");
  const ContactGeometry& g = *geometry_;
  auto t0 = Clock::now();
  fit_trees(x, /*rebuild=*/!tree_built_);
  positions_ = x;
  times_.refit = seconds_since(t0);
  t0 = Clock::now();
  const auto candidates =
      collision::triangle_tet_candidates(x, g.surface, g.tets, trees_, g.surface_body, trees_of_body_);
  times_.query = seconds_since(t0);
  std::size_t count = candidates.size();
  t0 = Clock::now();
  // A part whose own candidates pass the cap passes it for all of them: it finds no pairs.
  if (count <= candidate_cap_)
    find_pairs(x, candidates);
  else
    active_.clear();
  if (share_.join) share_.join(active_, count);
  times_.clip = seconds_since(t0);
  times_.candidates = static_cast<Index>(std::min<std::size_t>(count, std::numeric_limits<Index>::max()));
  overflowed_ = count > candidate_cap_;
  if (overflowed_) {
    active_.clear();
    return;
  }
  grow_pattern();
}

void CollisionSet::find_pairs(const Positions& x, const std::vector<std::pair<Index, Index>>& candidates) {
  // Fixed blocks of candidates, each filled by whichever thread takes it: concatenated in block
  // order, the kept pairs are in the candidates' order for any number of threads.
  constexpr std::size_t kBlock = 256;
  const ContactGeometry& g = *geometry_;
  const PairIntegrator& integrator = *integrator_;
  std::vector<std::vector<ActivePair>> per_block((candidates.size() + kBlock - 1) / kBlock);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, per_block.size()), [&](const auto& range) {
    for (std::size_t block = range.begin(); block != range.end(); ++block) {
      std::vector<ActivePair>& kept = per_block[block];
      ActivePair p;
      for (std::size_t k = block * kBlock, last = std::min(candidates.size(), k + kBlock); k < last; ++k) {
        const auto [f, t] = candidates[k];
        if (!tet_has_depth_[static_cast<std::size_t>(t)]) continue;
        const double penalty = pair_penalty(g, f, t);
        if (penalty == 0 || pair_is_immovable(g, f, t)) continue;
        p.triangle = f;
        p.tet = t;
        p.penalty = penalty;
        if (integrator.find_support(pair_geometry(g, x, f, t), p.support)) kept.push_back(p);
      }
    }
  });
  std::size_t total = 0;
  for (const auto& kept : per_block) total += kept.size();
  active_.clear();
  active_.reserve(total);
  for (const auto& kept : per_block) active_.insert(active_.end(), kept.begin(), kept.end());
}

void CollisionSet::grow_pattern() {
  // Only pairs never seen before can add blocks.
  bool grew = false;
  for (const ActivePair& p : active_) {
    if (!pairs_in_pattern_.insert(key(p.triangle, p.tet)).second) continue;
    const auto n = nodes(p);
    for (std::size_t i = 0; i < n.size(); ++i)
      for (std::size_t j = i + 1; j < n.size(); ++j)
        if (n[i] != n[j] && pattern_.insert(node_pair_key(n[i], n[j])).second) grew = true;
  }
  if (grew) ++revision_;
}

std::vector<std::pair<Index, Index>> CollisionSet::pair_indices() const {
  std::vector<std::pair<Index, Index>> out;
  out.reserve(active_.size());
  for (const auto& p : active_) out.emplace_back(p.triangle, p.tet);
  return out;
}

void CollisionSet::append_pattern(std::vector<std::pair<Index, Index>>& blocks) const {
  blocks.reserve(blocks.size() + pattern_.size());
  for (const std::uint64_t k : pattern_)
    blocks.emplace_back(static_cast<Index>(k >> 32), static_cast<Index>(k & 0xffffffffu));
}

void CollisionSet::set_penalty(const MatrixX& penalty) {
  const MatrixX& old = geometry_->penalty;
  if (penalty.rows() != old.rows() || penalty.cols() != old.cols())
    throw InputError(fmt::format("contact penalty: a {}x{} matrix for {} bodies", penalty.rows(), penalty.cols(),
                                 old.rows()));
  for (Index a = 0; a < old.rows(); ++a)
    for (Index b = 0; b < old.cols(); ++b) {
      const double e = penalty(a, b);
      if (!std::isfinite(e) || (old(a, b) > 0) != (e > 0) || e != penalty(b, a))
        throw InputError(fmt::format("contact penalty of bodies {} and {}: {} where it was {} (a penalty may only "
                                     "change between positive values and must stay symmetric)",
                                     a, b, e, old(a, b)));
    }
  auto geometry = std::make_shared<ContactGeometry>(*geometry_);
  geometry->penalty = penalty;
  geometry_ = std::move(geometry);
  for (ActivePair& p : active_) p.penalty = pair_penalty(*geometry_, p.triangle, p.tet);
}

void CollisionSet::set_pressure(VectorX pressure) {
  if (pressure.size() != 0 && pressure.size() != geometry_->depth.size())
    throw InputError(fmt::format("contact pressure: {} values for {} nodes", pressure.size(), geometry_->depth.size()));
  for (Index i = 0; i < pressure.size(); ++i)
    if (!std::isfinite(pressure[i]) || pressure[i] < 0)
      throw InputError(fmt::format("contact pressure at node {}: {} (must be finite and >= 0)", i, pressure[i]));
  pressure_ = std::move(pressure);
}

void CollisionSet::set_pressure_onset(double onset) {
  if (!std::isfinite(onset) || onset < 0)
    throw InputError(fmt::format("contact pressure onset: {} (must be finite and >= 0)", onset));
  pressure_onset_ = onset;
}

}  // namespace sinew::contact
