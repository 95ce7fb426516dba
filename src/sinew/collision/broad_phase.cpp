#include "sinew/collision/broad_phase.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sinew::collision {

std::vector<Aabb> tet_boxes(const Positions& x, const Tets& tets, double inflate) {
  std::vector<Aabb> boxes(static_cast<std::size_t>(tets.rows()));
  for (Index t = 0; t < tets.rows(); ++t) boxes[static_cast<std::size_t>(t)] = box_of(x, tets.row(t), inflate);
  return boxes;
}

std::vector<Aabb> triangle_boxes(const Positions& x, const Triangles& triangles, double inflate) {
  std::vector<Aabb> boxes(static_cast<std::size_t>(triangles.rows()));
  for (Index f = 0; f < triangles.rows(); ++f)
    boxes[static_cast<std::size_t>(f)] = box_of(x, triangles.row(f), inflate);
  return boxes;
}

bool shares_node(const Triangles& triangles, Index f, const Tets& tets, Index t) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j)
      if (triangles(f, i) == tets(t, j)) return true;
  return false;
}

namespace {

using Pairs = std::vector<std::pair<Index, Index>>;

/// The candidates of every triangle, found by query(f, report) (which calls report(t) for each
/// tet t whose box overlaps triangle f's), in fixed blocks of triangles filled by whichever thread
/// takes them and sorted within each triangle: concatenated in block order they are sorted, with
/// no sort of the whole list.
template <class Query>
Pairs candidates_by_blocks(const Triangles& triangles, const Tets& tets, Query&& query) {
  constexpr Index kBlock = 64;
  const Index num_triangles = static_cast<Index>(triangles.rows());
  std::vector<Pairs> per_block(static_cast<std::size_t>((num_triangles + kBlock - 1) / kBlock));
  using Blocks = tbb::blocked_range<std::size_t>;
  tbb::parallel_for(Blocks(0, per_block.size()), [&](const Blocks& range) {
    for (std::size_t block = range.begin(); block != range.end(); ++block) {
      Pairs& local = per_block[block];
      const Index first = static_cast<Index>(block) * kBlock, last = std::min(num_triangles, first + kBlock);
      for (Index f = first; f < last; ++f) {
        const std::size_t begin = local.size();
        query(f, [&](Index t) {
          if (!shares_node(triangles, f, tets, t)) local.emplace_back(f, t);
        });
        std::sort(local.begin() + static_cast<std::ptrdiff_t>(begin), local.end());
      }
    }
  });
  std::size_t total = 0;
  for (const Pairs& p : per_block) total += p.size();
  Pairs pairs;
  pairs.reserve(total);
  for (const Pairs& p : per_block) pairs.insert(pairs.end(), p.begin(), p.end());
  return pairs;
}

}  // namespace

std::vector<std::pair<Index, Index>> triangle_tet_candidates(const Positions& x, const Triangles& triangles,
                                                             const Tets& tets, const AabbTree& tet_tree,
                                                             double triangle_inflate) {
  // Programming error, not input: the caller built the tree over these tets.
  if (tet_tree.num_primitives() != tets.rows())
    throw std::invalid_argument("triangle_tet_candidates: tree over " + std::to_string(tet_tree.num_primitives()) +
                                " boxes for " + std::to_string(tets.rows()) + " tets");
  return candidates_by_blocks(triangles, tets, [&](Index f, const auto& report) {
    tet_tree.query(box_of(x, triangles.row(f), triangle_inflate), report);
  });
}

std::vector<Aabb> subset_boxes(const Positions& x, const Tets& tets, const std::vector<Index>& subset) {
  std::vector<Aabb> boxes(subset.size());
  for (std::size_t i = 0; i < subset.size(); ++i) boxes[i] = box_of(x, tets.row(subset[i]), 0.0);
  return boxes;
}

std::vector<std::pair<Index, Index>> triangle_tet_candidates(const Positions& x, const Triangles& triangles,
                                                             const Tets& tets,
                                                             const std::vector<TetSubsetTree>& trees,
                                                             const IndexVector& triangle_group,
                                                             const std::vector<std::vector<int>>& trees_of_group,
                                                             double triangle_inflate) {
  // Programming errors, not input: the caller built the trees and groups from these arrays.
  if (triangle_group.size() != triangles.rows())
    throw std::invalid_argument("triangle_tet_candidates: " + std::to_string(triangle_group.size()) + " groups for " +
                                std::to_string(triangles.rows()) + " triangles");
  for (const TetSubsetTree& t : trees)
    if (t.tree.num_primitives() != static_cast<Index>(t.tets.size()))
      throw std::invalid_argument("triangle_tet_candidates: a tree over " + std::to_string(t.tree.num_primitives()) +
                                  " boxes for " + std::to_string(t.tets.size()) + " tets");
  return candidates_by_blocks(triangles, tets, [&](Index f, const auto& report) {
    const auto group = static_cast<std::size_t>(triangle_group[f]);
    if (group >= trees_of_group.size()) return;
    const Aabb box = box_of(x, triangles.row(f), triangle_inflate);
    for (const int k : trees_of_group[group]) {
      const TetSubsetTree& subset = trees[static_cast<std::size_t>(k)];
      subset.tree.query(box, [&](Index primitive) { report(subset.tets[static_cast<std::size_t>(primitive)]); });
    }
  });
}

}  // namespace sinew::collision
