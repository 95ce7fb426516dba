#include "sinew/fem/elastic_energy.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "sinew/core/error.hpp"
#include "sinew/core/psd_projection.hpp"

namespace sinew::fem {
namespace {

/// Node gradients of one tet from P: V0 B^T vec(P), as 12-vector.
Vector12 tet_gradient(const Matrix3& P, const TetRestShape& rest) {
  const Matrix3 H = rest.volume * P * rest.Dm_inv.transpose();  // columns: forces on nodes 1..3
  Vector12 g;
  g.segment<3>(3) = H.col(0);
  g.segment<3>(6) = H.col(1);
  g.segment<3>(9) = H.col(2);
  g.segment<3>(0) = -(H.col(0) + H.col(1) + H.col(2));
  return g;
}

}  // namespace

ElasticEnergy::ElasticEnergy(const Positions& rest, const Tets& tets,
                             std::vector<material::MaterialPtr> tet_material, ElasticEnergyOptions options)
    : tets_(tets), project_hessians_(options.project_hessians) {
  if (tet_material.size() != static_cast<std::size_t>(tets.rows()))
    throw Error("ElasticEnergy: one material per tet expected");
  // Every tet's shape is checked (a degenerate one throws), and the deformable tets' are kept:
  // a rank's share keeps its own only (docs/mpi.md).
  const std::vector<TetRestShape> every_rest_shape = compute_rest_shapes(rest, tets);
  num_nodes_ = static_cast<Index>(rest.rows());
  const std::vector<bool>& evaluated = options.evaluated_tets;  // kept as active_ (and deformable_)
  if (!evaluated.empty()) {
    if (evaluated.size() != tet_material.size()) throw Error("ElasticEnergy: one evaluated-tet flag per tet expected");
    deformable_.resize(tet_material.size());
    for (std::size_t t = 0; t < tet_material.size(); ++t) deformable_[t] = tet_material[t] != nullptr;
  }
  const auto evaluates = [&](Index t) {
    return tet_material[static_cast<std::size_t>(t)] && (evaluated.empty() || evaluated[static_cast<std::size_t>(t)]);
  };
  Index count = 0;
  for (Index t = 0; t < tets.rows(); ++t) count += evaluates(t) ? 1 : 0;
  active_.reserve(static_cast<std::size_t>(count));
  rest_.reserve(static_cast<std::size_t>(count));
  material_.reserve(static_cast<std::size_t>(count));
  for (Index t = 0; t < tets.rows(); ++t)
    if (evaluates(t)) {
      active_.push_back(t);
      rest_.push_back(every_rest_shape[static_cast<std::size_t>(t)]);
      material_.push_back(std::move(tet_material[static_cast<std::size_t>(t)]));
    }

  incidence_offsets_.assign(static_cast<std::size_t>(num_nodes_) + 1, 0);
  for (Index t : active_)
    for (int i = 0; i < 4; ++i) ++incidence_offsets_[tets(t, i) + 1];
  for (Index a = 0; a < num_nodes_; ++a) incidence_offsets_[a + 1] += incidence_offsets_[a];
  incidence_.resize(incidence_offsets_.back());
  std::vector<Index> fill(incidence_offsets_.begin(), incidence_offsets_.end() - 1);
  for (std::size_t s = 0; s < active_.size(); ++s)
    for (int i = 0; i < 4; ++i) incidence_[fill[tets(active_[s], i)]++] = static_cast<Index>(4 * s + i);

  chunk_node_offsets_.assign(1, 0);
  std::vector<Index> nodes;
  for (std::size_t first = 0; first < active_.size(); first += kHessianChunk) {
    const std::size_t last = std::min(first + kHessianChunk, active_.size());
    nodes.clear();
    for (std::size_t s = first; s < last; ++s)
      for (int i = 0; i < 4; ++i) nodes.push_back(tets(active_[s], i));
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    chunk_nodes_.insert(chunk_nodes_.end(), nodes.begin(), nodes.end());
    chunk_node_offsets_.push_back(static_cast<Index>(chunk_nodes_.size()));
  }
}

double ElasticEnergy::value(const Positions& x) const {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, active_.size(), 512), 0.0,
      [&](const tbb::blocked_range<std::size_t>& r, double sum) {
        for (std::size_t s = r.begin(); s < r.end(); ++s) {
          const Index t = active_[s];
          const Matrix3 F = deformation_gradient(gather_tet(x, tets_, t), rest_[s].Dm_inv);
          sum += rest_[s].volume * material_[s]->evaluate(F, nullptr, nullptr);
        }
        return sum;
      },
      [](double a, double b) { return a + b; });
}

bool ElasticEnergy::is_valid(const Positions& x) const {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, active_.size(), 1024), true,
      [&](const tbb::blocked_range<std::size_t>& r, bool ok) {
        for (std::size_t s = r.begin(); s < r.end() && ok; ++s) {
          const Index t = active_[s];
          const Matrix3 F = deformation_gradient(gather_tet(x, tets_, t), rest_[s].Dm_inv);
          const double J = F.determinant();
          ok = std::isfinite(J) && J > 0;
        }
        return ok;
      },
      [](bool a, bool b) { return a && b; });
}

void ElasticEnergy::add_gradient(const Positions& x, NodalVectors& grad) const {
  std::vector<Vector12> local(active_.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, active_.size(), 512), [&](const auto& r) {
    for (std::size_t s = r.begin(); s < r.end(); ++s) {
      const Index t = active_[s];
      const Matrix3 F = deformation_gradient(gather_tet(x, tets_, t), rest_[s].Dm_inv);
      Matrix3 P;
      material_[s]->evaluate(F, &P, nullptr);
      local[s] = tet_gradient(P, rest_[s]);
    }
  });
  tbb::parallel_for(tbb::blocked_range<Index>(0, num_nodes_, 1024), [&](const auto& r) {
    for (Index a = r.begin(); a < r.end(); ++a) {
      Vector3 sum = Vector3::Zero();
      for (Index k = incidence_offsets_[a]; k < incidence_offsets_[a + 1]; ++k) {
        const Index slot = incidence_[k];
        sum += local[slot / 4].segment<3>(3 * (slot % 4));
      }
      grad.row(a) += sum.transpose();
    }
  });
}

void ElasticEnergy::hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const {
  pairs.reserve(pairs.size() + 6 * active_.size());
  for (Index t : active_)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) pairs.emplace_back(tets_(t, i), tets_(t, j));
}

void ElasticEnergy::whole_hessian_pattern(std::vector<std::pair<Index, Index>>& pairs) const {
  if (deformable_.empty()) return hessian_pattern(pairs);
  for (Index t = 0; t < tets_.rows(); ++t)
    if (deformable_[static_cast<std::size_t>(t)])
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) pairs.emplace_back(tets_(t, i), tets_(t, j));
}

void ElasticEnergy::bind_pattern(const BlockSparseMatrix& H) {
  const std::vector<Index>& moved = H.moved_block_index();
  if (bound_version_ != 0 && bound_version_ == H.previous_pattern_version() && !moved.empty() &&
      block_index_.size() == 16 * active_.size()) {
    // The pattern grew (new contact pairs): every tet block is still there, elsewhere.
    for (Index& k : block_index_) k = moved[static_cast<std::size_t>(k)];
    bound_version_ = H.pattern_version();
    return;
  }
  block_index_.resize(16 * active_.size());
  for (std::size_t s = 0; s < active_.size(); ++s) {
    const Index t = active_[s];
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const Index k = H.find(tets_(t, i), tets_(t, j));
        if (k < 0) throw Error("ElasticEnergy::bind_pattern: Hessian pattern lacks a tet block");
        block_index_[16 * s + 4 * i + j] = k;
      }
  }
  bound_version_ = H.pattern_version();
}

void ElasticEnergy::add_hessian(const Positions& x, BlockSparseMatrix& H) const {
  if (bound_version_ != H.pattern_version() || block_index_.size() != 16 * active_.size())
    throw Error("ElasticEnergy::add_hessian: call bind_pattern() after the pattern changes");
  // The tets' 12 x 12 Hessians are computed a chunk at a time (1,152 bytes per tet: the whole
  // mesh's at once was the largest buffer of a run, docs/solver.md) and gathered by rows: each
  // node's row blocks are written by one thread only, and in ascending tet order, so the sums are
  // the same to the last bit whatever the chunk size.
  std::vector<Matrix12> local(std::min(kHessianChunk, active_.size()));
  auto& values = H.values();
  for (std::size_t first = 0, chunk = 0; first < active_.size(); first += kHessianChunk, ++chunk) {
    const std::size_t last = std::min(first + kHessianChunk, active_.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last, 256), [&](const auto& r) {
      for (std::size_t s = r.begin(); s < r.end(); ++s) {
        const Index t = active_[s];
        const Matrix3 F = deformation_gradient(gather_tet(x, tets_, t), rest_[s].Dm_inv);
        Matrix3 P;
        Matrix9 dPdF;
        material_[s]->evaluate(F, &P, &dPdF);
        if (project_hessians_) dPdF = project_to_psd(dPdF);
        const Eigen::Matrix<double, 9, 12> B = deformation_gradient_jacobian(rest_[s].Dm_inv);
        // Coefficient-wise products: for 12 x 9 x 12 Eigen's general product would pack and block.
        const Eigen::Matrix<double, 12, 9> BtA = B.transpose().lazyProduct(dPdF);
        local[s - first].noalias() = rest_[s].volume * BtA.lazyProduct(B);
      }
    });
    const Index first_slot = static_cast<Index>(4 * first), end_slot = static_cast<Index>(4 * last);
    tbb::parallel_for(tbb::blocked_range<Index>(chunk_node_offsets_[chunk], chunk_node_offsets_[chunk + 1], 256),
                      [&](const auto& r) {
      for (Index n = r.begin(); n < r.end(); ++n) {
        const Index a = chunk_nodes_[static_cast<std::size_t>(n)];
        const auto begin = incidence_.begin() + incidence_offsets_[a], end = incidence_.begin() + incidence_offsets_[a + 1];
        for (auto it = std::lower_bound(begin, end, first_slot); it != end && *it < end_slot; ++it) {
          const Index slot = *it;
          const std::size_t s = static_cast<std::size_t>(slot / 4);
          const int i = slot % 4;
          for (int j = 0; j < 4; ++j)
            values[static_cast<std::size_t>(block_index_[16 * s + 4 * i + j])] +=
                local[s - first].block<3, 3>(3 * i, 3 * j);
        }
      }
    });
  }
}

TetMeasures compute_tet_measures(const Positions& x, const ElasticEnergy& elastic) {
  const Tets& tets = elastic.tets();
  const std::vector<Index>& deformable = elastic.deformable_tets();
  const std::vector<TetRestShape>& rest = elastic.rest_shapes();  // in deformable's order
  TetMeasures m;
  m.J = VectorX::Ones(tets.rows());
  m.von_mises = VectorX::Zero(tets.rows());
  tbb::parallel_for(std::size_t(0), deformable.size(), [&](std::size_t s) {
    const Index t = deformable[s];
    const Matrix3 F = deformation_gradient(gather_tet(x, tets, t), rest[s].Dm_inv);
    const double J = F.determinant();
    m.J[t] = J;
    if (!(J > 0)) {
      m.von_mises[t] = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    Matrix3 P;
    elastic.materials()[s]->evaluate(F, &P, nullptr);
    const Matrix3 sigma = P * F.transpose() / J;
    const Matrix3 dev = sigma - sigma.trace() / 3.0 * Matrix3::Identity();
    m.von_mises[t] = std::sqrt(1.5 * dev.squaredNorm());
  });
  return m;
}

}  // namespace sinew::fem
