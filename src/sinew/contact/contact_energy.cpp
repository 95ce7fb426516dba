#include "sinew/contact/contact_energy.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "sinew/collision/broad_phase.hpp"
#include "sinew/core/error.hpp"

namespace sinew::contact {
namespace {

std::uint64_t block_key(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

/// False when the tet lies on one side of the triangle's plane (touching it at most along an edge
/// within round-off), so triangle ∩ tet has no area: the pair can be rejected before clipping.
/// A tet with a face in the plane is kept (its intersection with the triangle can have area).
bool tet_crosses_triangle_plane(const PairGeometry& pg) {
  const Vector3 a = pg.triangle.row(0);
  const Vector3 normal = (Vector3(pg.triangle.row(1)) - a).cross(Vector3(pg.triangle.row(2)) - a);
  const double length = normal.norm();
  if (!(length > 0)) return true;  // degenerate triangle: let the clip and the integral decide
  double scale = 0;
  for (int k = 1; k < 4; ++k) scale = std::max(scale, (pg.tet.row(k) - pg.tet.row(0)).cwiseAbs().maxCoeff());
  const double tolerance = 1e-12 * scale;
  int below = 0, above = 0, on = 0;
  for (int k = 0; k < 4; ++k) {
    const double d = normal.dot(Vector3(pg.tet.row(k)) - a) / length;
    if (d > tolerance)
      ++above;
    else if (d < -tolerance)
      ++below;
    else
      ++on;
  }
  if (above > 0 && below > 0) return true;
  return on >= 3;
}

}  // namespace

ContactEnergy::ContactEnergy(ContactGeometry geometry, ContactOptions options)
    : geometry_(std::move(geometry)), options_(options) {
  const auto& g = geometry_;
  const Index bodies = static_cast<Index>(g.penalty.rows());
  if (g.penalty.cols() != bodies) throw InputError("contact: the penalty matrix must be square (bodies x bodies)");
  if (g.surface_body.size() != g.surface.rows())
    throw InputError("contact: surface_body must have one entry per surface triangle");
  if (g.tet_body.size() != g.tets.rows()) throw InputError("contact: tet_body must have one entry per tet");
  for (Index i = 0; i < bodies; ++i)
    for (Index j = 0; j < bodies; ++j) {
      const double e = g.penalty(i, j);
      if (!std::isfinite(e) || e < 0)
        throw InputError(fmt::format("contact: the penalty between bodies {} and {} is {} (must be finite and >= 0)",
                                     i, j, e));
      if (e != g.penalty(j, i)) throw InputError("contact: the penalty matrix must be symmetric");
    }
  auto check_scale = [](const VectorX& scale, Index expected, const char* what) {
    if (scale.size() == 0) return;
    if (scale.size() != expected)
      throw InputError(fmt::format("contact: {} penalty scale has {} entries for {} {}s", what, scale.size(),
                                   expected, what));
    for (Index k = 0; k < scale.size(); ++k)
      if (!std::isfinite(scale[k]) || scale[k] <= 0)
        throw InputError(fmt::format("contact: the penalty scale of {} {} is {} (must be finite and > 0)", what, k,
                                     scale[k]));
  };
  check_scale(g.surface_penalty_scale, g.surface.rows(), "triangle");
  check_scale(g.tet_penalty_scale, g.tets.rows(), "tet");
  for (Index k = 0; k < g.surface_body.size(); ++k)
    if (g.surface_body[k] < 0 || g.surface_body[k] >= bodies)
      throw InputError(fmt::format("contact: surface triangle {} has body {} (there are {} bodies)", k,
                                   g.surface_body[k], bodies));
  for (Index k = 0; k < g.tet_body.size(); ++k)
    if (g.tet_body[k] < 0 || g.tet_body[k] >= bodies)
      throw InputError(fmt::format("contact: tet {} has body {} (there are {} bodies)", k, g.tet_body[k], bodies));
  const Index nodes = static_cast<Index>(g.depth.size());
  for (Index a = 0; a < nodes; ++a)
    if (!std::isfinite(g.depth[a]) || g.depth[a] < 0)
      throw InputError(fmt::format("contact: the material depth of node {} is {} (must be finite and >= 0)", a,
                                   g.depth[a]));
  if ((g.surface.size() > 0 && (g.surface.minCoeff() < 0 || g.surface.maxCoeff() >= nodes)) ||
      (g.tets.size() > 0 && (g.tets.minCoeff() < 0 || g.tets.maxCoeff() >= nodes)))
    throw InputError("contact: a surface triangle or tet refers to a node without a material depth");
  tet_has_depth_.resize(static_cast<std::size_t>(g.tets.rows()));
  for (Index t = 0; t < g.tets.rows(); ++t) {
    double m = 0;
    for (int k = 0; k < 4; ++k) m = std::max(m, g.depth[g.tets(t, k)]);
    tet_has_depth_[static_cast<std::size_t>(t)] = m > 0;
  }
}

std::array<Index, 7> ContactEnergy::pair_nodes(const ActivePair& p) const {
  const auto& f = geometry_.surface;
  const auto& T = geometry_.tets;
  return {f(p.triangle, 0), f(p.triangle, 1), f(p.triangle, 2), T(p.tet, 0), T(p.tet, 1), T(p.tet, 2), T(p.tet, 3)};
}

PairGeometry ContactEnergy::pair_geometry(const Positions& x, const ActivePair& p) const {
  PairGeometry pg;
  for (int k = 0; k < 3; ++k) pg.triangle.row(k) = x.row(geometry_.surface(p.triangle, k));
  for (int k = 0; k < 4; ++k) {
    const Index a = geometry_.tets(p.tet, k);
    pg.tet.row(k) = x.row(a);
    pg.depth[k] = geometry_.depth[a];
  }
  return pg;
}

void ContactEnergy::require_current(const Positions& x) const {
  if (x.rows() != current_x_.rows() || !(x.array() == current_x_.array()).all())
    throw std::logic_error("ContactEnergy: update(x) must be called before evaluating at a new x");
}

void ContactEnergy::begin_step(const Positions& x) {
  // Programming error, not input: the solver passes configurations of the contact geometry's mesh.
  if (x.rows() != geometry_.depth.size())
    throw std::invalid_argument(fmt::format("ContactEnergy::begin_step: x has {} rows, the contact geometry {} nodes",
                                            x.rows(), geometry_.depth.size()));
  tree_.build(collision::tet_boxes(x, geometry_.tets));
  tree_built_ = true;
  current_x_.resize(0, 3);  // force the next update() to recompute the pairs
  update(x);
}

void ContactEnergy::update(const Positions& x) {
  if (x.rows() == current_x_.rows() && (x.array() == current_x_.array()).all()) return;
  // Programming error, not input (as in begin_step).
  if (x.rows() != geometry_.depth.size())
    throw std::invalid_argument(fmt::format("ContactEnergy::update: x has {} rows, the contact geometry {} nodes",
                                            x.rows(), geometry_.depth.size()));
  using Clock = std::chrono::steady_clock;
  auto seconds_since = [](Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  auto t0 = Clock::now();
  if (!tree_built_) {
    tree_.build(collision::tet_boxes(x, geometry_.tets));
    tree_built_ = true;
  } else {
    tree_.refit(collision::tet_boxes(x, geometry_.tets));
  }
  current_x_ = x;
  times_.refit = seconds_since(t0);
  t0 = Clock::now();
  const auto candidates = collision::triangle_tet_candidates(x, geometry_.surface, geometry_.tets, tree_);
  times_.query = seconds_since(t0);
  times_.candidates = static_cast<Index>(candidates.size());
  const std::size_t cap = options_.candidate_cap > 0
                              ? options_.candidate_cap
                              : std::max<std::size_t>(100000, 20 * static_cast<std::size_t>(geometry_.tets.rows()));
  overflowed_ = candidates.size() > cap;
  if (overflowed_) {
    active_.clear();
    times_.clip = 0;
    return;
  }
  t0 = Clock::now();
  // Narrow phase. Most candidates are neighbours that merely touch the triangle's plane from one
  // side; they are rejected by the plane test before clipping, and only kept pairs are stored.
  struct Kept {
    std::size_t candidate;
    ActivePair pair;
  };
  tbb::enumerable_thread_specific<std::vector<Kept>> kept_per_thread;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, candidates.size(), 256), [&](const auto& range) {
    std::vector<Kept>& kept = kept_per_thread.local();
    Kept item;
    for (std::size_t k = range.begin(); k != range.end(); ++k) {
      const auto [f, t] = candidates[k];
      if (!tet_has_depth_[static_cast<std::size_t>(t)]) continue;
      const double penalty = pair_penalty(f, t);
      if (penalty == 0) continue;
      ActivePair& p = item.pair;
      p.triangle = f;
      p.tet = t;
      p.penalty = penalty;
      const PairGeometry pg = pair_geometry(x, p);
      bool keep = false;
      if (options_.method == ContactMethod::Area) {
        if (!tet_crosses_triangle_plane(pg)) continue;
        p.polygon = collision::clip_triangle_tet(pg.triangle, pg.tet);
        keep = p.polygon.count >= 3;
      } else {
        p.points = collision::triangle_vertices_in_tet(pg.triangle, pg.tet);
        keep = p.points.count > 0;
      }
      if (keep) {
        item.candidate = k;
        kept.push_back(item);
      }
    }
  });
  std::vector<Kept> all;
  for (auto& kept : kept_per_thread) all.insert(all.end(), kept.begin(), kept.end());
  std::sort(all.begin(), all.end(), [](const Kept& a, const Kept& b) { return a.candidate < b.candidate; });
  active_.clear();
  active_.reserve(all.size());
  for (const Kept& item : all) active_.push_back(item.pair);
  times_.clip = seconds_since(t0);

  // Pattern: only pairs never seen before can add blocks.
  bool grew = false;
  for (const ActivePair& p : active_) {
    const std::uint64_t pair_key =
        (static_cast<std::uint64_t>(static_cast<std::uint32_t>(p.triangle)) << 32) | static_cast<std::uint32_t>(p.tet);
    if (!pairs_in_pattern_.insert(pair_key).second) continue;
    const auto nodes = pair_nodes(p);
    for (int i = 0; i < 7; ++i)
      for (int j = i + 1; j < 7; ++j)
        if (nodes[static_cast<std::size_t>(i)] != nodes[static_cast<std::size_t>(j)] &&
            pattern_.insert(block_key(nodes[static_cast<std::size_t>(i)], nodes[static_cast<std::size_t>(j)])).second)
          grew = true;
  }
  if (grew) ++revision_;
}

std::vector<std::pair<Index, Index>> ContactEnergy::active_pairs() const {
  std::vector<std::pair<Index, Index>> out;
  out.reserve(active_.size());
  for (const auto& p : active_) out.emplace_back(p.triangle, p.tet);
  return out;
}

bool ContactEnergy::is_valid(const Positions& x) const {
  require_current(x);
  return !overflowed_;
}

double ContactEnergy::value(const Positions& x) const {
  require_current(x);
  if (overflowed_) return std::numeric_limits<double>::infinity();
  std::vector<double> values(active_.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, active_.size(), 64), [&](const auto& range) {
    for (std::size_t k = range.begin(); k != range.end(); ++k) {
      const ActivePair& p = active_[k];
      const PairGeometry pg = pair_geometry(x, p);
      const double I = options_.method == ContactMethod::Area ? area_integral(pg, p.polygon)
                                                              : point_integral(pg, p.points);
      values[k] = 0.5 * p.penalty * I;
    }
  });
  return std::accumulate(values.begin(), values.end(), 0.0);
}

void ContactEnergy::add_gradient(const Positions& x, NodalVectors& grad) const {
  require_current(x);
  if (overflowed_)
    throw Error(fmt::format("contact: {} candidate pairs at this configuration (more than the cap): the bodies "
                            "overlap far beyond what contact can resolve",
                            times_.candidates));
  std::vector<PairVector> gradients(active_.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, active_.size(), 64), [&](const auto& range) {
    for (std::size_t k = range.begin(); k != range.end(); ++k) {
      const ActivePair& p = active_[k];
      const PairGeometry pg = pair_geometry(x, p);
      if (options_.method == ContactMethod::Area)
        area_integral_gradient(pg, p.polygon, gradients[k]);
      else
        point_integral_gradient(pg, p.points, gradients[k]);
      gradients[k] *= 0.5 * p.penalty;
    }
  });
  for (std::size_t k = 0; k < active_.size(); ++k) {
    const auto nodes = pair_nodes(active_[k]);
    for (int i = 0; i < 7; ++i) grad.row(nodes[static_cast<std::size_t>(i)]) += gradients[k].segment<3>(3 * i).transpose();
  }
}

void ContactEnergy::hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const {
  pairs.reserve(pairs.size() + pattern_.size());
  for (const std::uint64_t key : pattern_)
    pairs.emplace_back(static_cast<Index>(key >> 32), static_cast<Index>(key & 0xffffffffu));
}

void ContactEnergy::add_hessian(const Positions& x, BlockSparseMatrix& H) const {
  require_current(x);
  // In chunks: pair Hessians and their block indices in parallel, then a serial scatter (which
  // is cheap), so memory stays bounded by the chunk.
  constexpr std::size_t kChunk = 2048;
  std::vector<PairMatrix> hessians(std::min(kChunk, active_.size()));
  std::vector<std::array<Index, 49>> blocks(hessians.size());
  for (std::size_t begin = 0; begin < active_.size(); begin += kChunk) {
    const std::size_t end = std::min(active_.size(), begin + kChunk);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, 16), [&](const auto& range) {
      PairVector gradient;
      for (std::size_t k = range.begin(); k != range.end(); ++k) {
        const ActivePair& p = active_[k];
        const PairGeometry pg = pair_geometry(x, p);
        PairMatrix& hessian = hessians[k - begin];
        if (options_.method == ContactMethod::Area)
          area_integral_hessian(pg, p.polygon, options_.hessian, gradient, hessian);
        else
          point_integral_hessian(pg, p.points, options_.hessian, gradient, hessian);
        hessian *= 0.5 * p.penalty;
        const auto nodes = pair_nodes(p);
        for (int i = 0; i < 7; ++i)
          for (int j = 0; j < 7; ++j)
            blocks[k - begin][static_cast<std::size_t>(7 * i + j)] =
                H.find(nodes[static_cast<std::size_t>(i)], nodes[static_cast<std::size_t>(j)]);
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

ContactStatistics ContactEnergy::statistics(const Positions& x) {
  update(x);
  ContactStatistics s;
  const Index bodies = num_bodies();
  s.body_pair_force.assign(static_cast<std::size_t>(bodies * bodies), Vector3::Zero());
  s.nodal_force = NodalVectors::Zero(x.rows(), 3);
  s.nodal_pressure = VectorX::Zero(x.rows());
  s.pairs = static_cast<Index>(active_.size());
  s.energy = value(x);
  double depth_integral = 0;
  // Per-node contact force, and the force each body pair exerts.
  std::vector<Index> node_body(static_cast<std::size_t>(x.rows()), -1);
  for (Index t = 0; t < geometry_.tets.rows(); ++t)
    for (int k = 0; k < 4; ++k) node_body[static_cast<std::size_t>(geometry_.tets(t, k))] = geometry_.tet_body[t];
  for (Index f = 0; f < geometry_.surface.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      node_body[static_cast<std::size_t>(geometry_.surface(f, k))] = geometry_.surface_body[f];
  NodalVectors self_force = NodalVectors::Zero(x.rows(), 3);
  for (const ActivePair& p : active_) {
    const PairGeometry pg = pair_geometry(x, p);
    PairVector gradient;
    PolygonMoments m;
    if (options_.method == ContactMethod::Area) {
      area_integral_gradient(pg, p.polygon, gradient);
      m = area_moments(pg, p.polygon);
    } else {
      point_integral_gradient(pg, p.points, gradient);
      m = point_moments(pg, p.points);
    }
    gradient *= -0.5 * p.penalty;  // force
    s.area += m.area;
    depth_integral += m.depth_integral;
    s.max_penetration = std::max(s.max_penetration, m.max_depth);
    const auto nodes = pair_nodes(p);
    const Index bt = geometry_.surface_body[p.triangle], be = geometry_.tet_body[p.tet];
    for (int i = 0; i < 7; ++i) {
      const Vector3 f = gradient.segment<3>(3 * i);
      const Index a = nodes[static_cast<std::size_t>(i)];
      s.nodal_force.row(a) += f.transpose();
      const Index body = node_body[static_cast<std::size_t>(a)];
      if (bt == be) {
        self_force.row(a) += f.transpose();
      } else {
        const Index lo = std::min(bt, be), hi = std::max(bt, be);
        if (body == lo) s.body_pair_force[static_cast<std::size_t>(lo * bodies + hi)] += f;
      }
    }
  }
  if (s.area > 0) s.mean_penetration = depth_integral / s.area;
  // Self-contact: half the sum of the magnitudes of the nodal forces from pairs within one body.
  for (Index a = 0; a < x.rows(); ++a) {
    const Index body = node_body[static_cast<std::size_t>(a)];
    if (body >= 0) s.body_pair_force[static_cast<std::size_t>(body * bodies + body)].x() += 0.5 * self_force.row(a).norm();
  }
  // Pressure: |nodal force| over a third of the current area of the surface triangles around the node.
  VectorX node_area = VectorX::Zero(x.rows());
  for (Index f = 0; f < geometry_.surface.rows(); ++f) {
    const Vector3 a = x.row(geometry_.surface(f, 0)), b = x.row(geometry_.surface(f, 1)),
                  c = x.row(geometry_.surface(f, 2));
    const double area = 0.5 * (b - a).cross(c - a).norm();
    for (int k = 0; k < 3; ++k) node_area[geometry_.surface(f, k)] += area / 3;
  }
  for (Index a = 0; a < x.rows(); ++a)
    if (node_area[a] > 0) s.nodal_pressure[a] = s.nodal_force.row(a).norm() / node_area[a];
  return s;
}

}  // namespace sinew::contact
