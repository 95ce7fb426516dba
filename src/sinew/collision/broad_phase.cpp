#include "sinew/collision/broad_phase.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
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

std::vector<std::pair<Index, Index>> triangle_tet_candidates(const Positions& x, const Triangles& triangles,
                                                             const Tets& tets, const AabbTree& tet_tree,
                                                             double triangle_inflate) {
  // Programming error, not input: the caller built the tree over these tets.
  if (tet_tree.num_primitives() != tets.rows())
    throw std::invalid_argument("triangle_tet_candidates: tree over " + std::to_string(tet_tree.num_primitives()) +
                                " boxes for " + std::to_string(tets.rows()) + " tets");
  using Pairs = std::vector<std::pair<Index, Index>>;
  tbb::enumerable_thread_specific<Pairs> per_thread;
  tbb::parallel_for(tbb::blocked_range<Index>(0, static_cast<Index>(triangles.rows()), 64),
                    [&](const tbb::blocked_range<Index>& range) {
                      Pairs& local = per_thread.local();
                      for (Index f = range.begin(); f != range.end(); ++f) {
                        const Aabb box = box_of(x, triangles.row(f), triangle_inflate);
                        tet_tree.query(box, [&](Index t) {
                          if (!shares_node(triangles, f, tets, t)) local.emplace_back(f, t);
                        });
                      }
                    });
  std::size_t total = 0;
  for (const Pairs& p : per_thread) total += p.size();
  Pairs pairs;
  pairs.reserve(total);
  for (const Pairs& p : per_thread) pairs.insert(pairs.end(), p.begin(), p.end());
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace sinew::collision
